// foldSheetText: the plain-text PLC sheet printed by `valvetune-cli fold plan`. Its own words go
// through tr() (the CLI's --lang installs the catalogue); the texts of the Qt-free plan (node
// addresses, layouts) are still {en, de} pairs, shown in `lang`.
#include "core/hex.h"
#include "fold_export.h"

#include <QCoreApplication>

namespace vt::model {

using dev::Language;

namespace {

class FoldSheetText
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::FoldSheetText)

public:
    static QString text(const PlcConfig &c, const FoldPlan &plan, Language lang);
};

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

// A label padded to its column; width in characters, as a terminal shows them.
QString pad(const QString &s, int width)
{
    return s.leftJustified(width);
}

QString hex2(unsigned v)
{
    return QStringLiteral("0x%1").arg(
        QString::number(v & 0xFFu, 16).toUpper().rightJustified(2, QLatin1Char('0')));
}

QString byteLine(const PlcImageByte &b, Language lang)
{
    return QStringLiteral("  %1  %2%3\n")
        .arg(b.offset, 4)
        .arg(pad(q(b.field), 9), plcText(b.text, lang));
}

QString bitNames(const std::array<dev::hcs::BitMeaning, 8> &bits)
{
    QStringList names;
    for (const auto &bit : bits)
        if (bit.used)
            names << hex2(bit.mask) + QLatin1Char(' ') + q(std::string(bit.name));
    return names.join(QStringLiteral(", "));
}

QString FoldSheetText::text(const PlcConfig &c, const FoldPlan &plan, Language lang)
{
    QString o;
    o += tr("Fold plan: %1 (%2), %n module(s)", nullptr, c.modules)
             .arg(foldNodeTitle(c.node), q(std::string(foldNodeKey(c.node)))) +
         QLatin1Char('\n');
    if (!plan.title.empty())
        o += pad(tr("Title:"), 13) + q(plan.title) + QLatin1Char('\n');
    o += pad(tr("GSD file:"), 13) + q(c.gsdFile) + QLatin1Char('\n');
    o += pad(tr("Device:"), 13) + q(c.gsdDevice) + QLatin1Char('\n');
    o += pad(tr("GSD module:"), 13) + q(c.gsdModule) + QLatin1Char('\n');
    o += pad(tr("Output:"), 13) +
         tr("%1 bytes (PLC to node, CMD 15 request, SNUM = %2)").arg(c.outputBytes).arg(c.snum) +
         QLatin1Char('\n');
    o += pad(tr("Input:"), 13) +
         tr("%1 bytes (node to PLC, one module per answer)").arg(c.inputBytes) + QLatin1Char('\n');
    if (c.moduleOutputBytes != c.outputBytes || c.moduleInputBytes != c.inputBytes)
        o += pad(tr("Reserved:"), 13) +
             tr("%1 / %2 bytes out / in by the GSD module")
                 .arg(c.moduleOutputBytes)
                 .arg(c.moduleInputBytes) +
             QLatin1Char('\n');
    o += pad(tr("Source:"), 13) + plcText(c.gsdNote, lang) + QLatin1Char('\n');

    o += QLatin1Char('\n') + tr("Output image (PLC to node)") + QLatin1Char('\n');
    o += QStringLiteral("  ") + pad(tr("byte"), 4) + QStringLiteral("  ") + pad(tr("field"), 9) +
         tr("meaning") + QLatin1Char('\n');
    for (const PlcImageByte &b : c.output)
        if (b.module < 0)
            o += byteLine(b, lang);
    for (const PlcModuleSection &s : c.sections) {
        const FoldModule *m = s.module < static_cast<int>(plan.modules.size())
                                  ? &plan.modules[static_cast<std::size_t>(s.module)]
                                  : nullptr;
        const auto &info = dev::hcs::profileInfo(s.profile);
        const QString last = QString::number(s.outputFirst + s.outputLength - 1);
        if (m) {
            QString where = foldAddressText(c.node, *m);
            if (!m->name.empty())
                where += QStringLiteral(", ") + q(m->name);
            o += tr("Module %1 (%2): %3, output bytes %4..%5")
                     .arg(QString::number(s.module + 1), where, q(info.title.in(lang)),
                          QString::number(s.outputFirst), last);
        } else {
            o += tr("Module %1: %2, output bytes %3..%4")
                     .arg(QString::number(s.module + 1), q(info.title.in(lang)),
                          QString::number(s.outputFirst), last);
        }
        o += QLatin1Char('\n');
        for (const PlcImageByte &b : c.output)
            if (b.module == s.module)
                o += byteLine(b, lang);
        const QString indent(8, QLatin1Char(' '));
        o += indent +
             tr("answer with SADR = %1: VALUE1 = %2; VALUE2 = %3")
                 .arg(QString::number(s.sadr),
                      q(std::string(info.response1.parameter) + " " + info.response1.text.in(lang)),
                      q(std::string(info.response2.parameter) + " " +
                        info.response2.text.in(lang))) +
             QLatin1Char('\n');
        const QString control = bitNames(s.controlBits);
        o += indent +
             tr("control byte bits: %1").arg(control.isEmpty() ? QStringLiteral("-") : control) +
             QLatin1Char('\n');
        const QString high = bitNames(s.statusHighBits);
        o += indent + tr("status high byte: %1").arg(high.isEmpty() ? QStringLiteral("-") : high) +
             QLatin1Char('\n');
        const QString low = bitNames(s.statusLowBits);
        o +=
            indent +
            tr("status low byte: %1")
                .arg(low.isEmpty() ? tr("no signals in this mode (error number while ERROR is set)")
                                   : tr("%1 (error number while ERROR is set)").arg(low)) +
            QLatin1Char('\n');
    }

    o += QLatin1Char('\n') + tr("Input image (node to PLC, multiplexed: SADR names the module)") +
         QLatin1Char('\n');
    for (const PlcImageByte &b : c.input)
        o += byteLine(b, lang);

    o += QLatin1Char('\n') +
         tr("Example CMD 15 telegram (TADR 0x01, control byte 0x00, VALUE1 = 1000 = 1.000 V, "
            "VALUE2 = 0 for every module):") +
         QStringLiteral("\n  ") + q(dev::toHex(c.exampleRequestBytes)) + QLatin1Char('\n');
    return o;
}

} // namespace

QString foldSheetText(const PlcConfig &c, const FoldPlan &plan, Language lang)
{
    return FoldSheetText::text(c, plan, lang);
}

} // namespace vt::model
