#include "fault_spec.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSet>
#include <QStringList>
#include <cmath>

namespace vt::link {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("vt::link::FaultSpec", text);
}

QString number(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

void appendRates(QStringList &items, const QString &prefix, const FaultRates &r)
{
    if (r.drop != 0.0)
        items << prefix + QStringLiteral("drop=") + number(r.drop);
    if (r.corrupt != 0.0)
        items << prefix + QStringLiteral("corrupt=") + number(r.corrupt);
    if (r.delayMs != 0)
        items << prefix + QStringLiteral("delay=") + QString::number(r.delayMs);
}

} // namespace

QString FaultSpecError::text() const
{
    if (item.isEmpty())
        return tr("fault spec: %1").arg(message);
    return tr("fault spec item '%1': %2").arg(item, message);
}

QString FaultSpec::toString() const
{
    QStringList items;
    if (tx == rx) {
        appendRates(items, QString(), tx);
    } else {
        appendRates(items, QStringLiteral("tx."), tx);
        appendRates(items, QStringLiteral("rx."), rx);
    }
    if (cutAfterFrames)
        items << QStringLiteral("cut=") + QString::number(*cutAfterFrames);
    items << QStringLiteral("seed=") + QString::number(seed);
    return items.join(QLatin1Char(','));
}

dev::Result<FaultSpec, FaultSpecError> parseFaultSpec(QStringView text)
{
    FaultSpec spec;
    QSet<QString> seen;
    const QStringList items = text.toString().split(QLatin1Char(','));
    for (const QString &raw : items) {
        const QString item = raw.trimmed();
        if (item.isEmpty()) {
            if (items.size() == 1)
                break; // a blank spec
            return FaultSpecError{QString(), tr("empty item (two commas in a row?)")};
        }
        const qsizetype eq = item.indexOf(QLatin1Char('='));
        if (eq < 0)
            return FaultSpecError{item, tr("expected key=value")};
        const QString fullKey = item.left(eq).trimmed().toLower();
        const QString value = item.mid(eq + 1).trimmed();
        if (seen.contains(fullKey))
            return FaultSpecError{item, tr("given twice")};
        seen.insert(fullKey);

        QString key = fullKey;
        bool toTx = true;
        bool toRx = true;
        if (key.startsWith(QLatin1String("tx."))) {
            toRx = false;
            key = key.mid(3);
        } else if (key.startsWith(QLatin1String("rx."))) {
            toTx = false;
            key = key.mid(3);
        }
        const bool directional = !(toTx && toRx);

        bool ok = false;
        if (key == QLatin1String("drop") || key == QLatin1String("corrupt")) {
            const double p = value.toDouble(&ok);
            if (!ok || !std::isfinite(p) || p < 0.0 || p > 1.0)
                return FaultSpecError{item, tr("probability must be a number between 0 and 1")};
            double FaultRates::*field =
                key == QLatin1String("drop") ? &FaultRates::drop : &FaultRates::corrupt;
            if (toTx)
                spec.tx.*field = p;
            if (toRx)
                spec.rx.*field = p;
        } else if (key == QLatin1String("delay")) {
            const int ms = value.toInt(&ok);
            if (!ok || ms < 0 || ms > FaultSpec::kMaxDelayMs)
                return FaultSpecError{item, tr("delay must be whole milliseconds, 0 to 60000")};
            if (toTx)
                spec.tx.delayMs = ms;
            if (toRx)
                spec.rx.delayMs = ms;
        } else if (key == QLatin1String("cut") && !directional) {
            const qulonglong frames = value.toULongLong(&ok);
            if (!ok)
                return FaultSpecError{item, tr("cut must be a whole number of frames")};
            spec.cutAfterFrames = frames;
        } else if (key == QLatin1String("seed") && !directional) {
            const uint seed = value.toUInt(&ok);
            if (!ok)
                return FaultSpecError{item, tr("seed must be a whole number from 0 to 4294967295")};
            spec.seed = seed;
        } else if (directional && (key == QLatin1String("cut") || key == QLatin1String("seed"))) {
            return FaultSpecError{item, tr("cut and seed apply to both directions; drop the "
                                           "tx./rx. prefix")};
        } else {
            return FaultSpecError{item, tr("unknown key (known: drop, corrupt, delay, cut, seed; "
                                           "drop, corrupt and delay may take a tx. or rx. "
                                           "prefix)")};
        }
    }
    return spec;
}

} // namespace vt::link
