#include "tuning_journal.h"

#include "core/vt_assert.h"
#include "dict/cooking.h"

#include <algorithm>

namespace vt::model {

namespace {

QString valueText(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang)
{
    if (dev::isText(value))
        return QString::fromStdString(std::get<std::string>(value));
    return QString::fromStdString(dev::formatValue(row, dev::rawNumber(value), lang));
}

} // namespace

QString writeMarkerText(const WriteItem &item, dev::Language lang)
{
    VT_ASSERT(item.row, return {});
    const QString name = QString::fromStdString(item.row->name);
    const QString to = valueText(*item.row, item.value, lang);
    if (!item.before)
        return QStringLiteral("%1 → %2").arg(name, to);
    return QStringLiteral("%1 %2 → %3").arg(name, valueText(*item.row, *item.before, lang), to);
}

TuningJournal::TuningJournal(qsizetype maxMarkers)
    : m_maxMarkers(std::max<qsizetype>(1, maxMarkers))
{
}

int TuningJournal::addWrites(double t, int module, const std::vector<WriteItem> &items,
                             dev::Language lang, bool modulePrefix)
{
    int added = 0;
    for (const WriteItem &item : items) {
        if (!item.row ||
            (item.status != WriteStatus::Verified && item.status != WriteStatus::Written))
            continue;
        const QString text = writeMarkerText(item, lang);
        add(t, modulePrefix ? tr("module %1: %2").arg(module).arg(text) : text);
        ++added;
    }
    return added;
}

void TuningJournal::add(double t, const QString &text)
{
    // Writes are journalled as they finish, so times arrive in order; keep the order anyway.
    const auto at = std::upper_bound(m_markers.begin(), m_markers.end(), t,
                                     [](double time, const SampleMarker &m) { return time < m.t; });
    m_markers.insert(at, SampleMarker{t, text.left(SampleStore::kMaxMarkerText)});
    while (static_cast<qsizetype>(m_markers.size()) > m_maxMarkers)
        m_markers.pop_front();
}

std::vector<SampleMarker> TuningJournal::markersIn(double t0, double t1) const
{
    std::vector<SampleMarker> out;
    for (const SampleMarker &m : m_markers) {
        if (m.t >= t0 && m.t <= t1)
            out.push_back(m);
    }
    return out;
}

} // namespace vt::model
