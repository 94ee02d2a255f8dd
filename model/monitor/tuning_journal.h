// TuningJournal: the monitor's record of parameter writes, one
// marker per value that reached the device, on the samples' time axis ("C1.07 0.800 V → 1.000 V").
// A plain value owned by the MonitorSession; GUI thread only.
#pragma once

#include "core/local_text.h"
#include "model/monitor/sample_store.h"
#include "model/session/write_record.h"

#include <QCoreApplication>
#include <deque>
#include <vector>

namespace vt::model {

// "C1.07 0.800 V → 1.000 V"; "C1.07 → 1.000 V" when the old value is unknown. Numbers and enum
// labels in `lang` ("0,800 V" in German).
QString writeMarkerText(const WriteItem &item, dev::Language lang);

class TuningJournal
{
    Q_DECLARE_TR_FUNCTIONS(vt::model::TuningJournal)
public:
    explicit TuningJournal(qsizetype maxMarkers = SampleStore::kDefaultMaxMarkers);

    // Marks at time `t` every item the device now holds because of this write (Verified or
    // Written; Unchanged items were not sent and leave no mark). `modulePrefix`: name the module
    // ("module 2: C1.07 …") when several are connected. Returns how many markers were added.
    int addWrites(double t, int module, const std::vector<WriteItem> &items, dev::Language lang,
                  bool modulePrefix);
    void add(double t, const QString &text);
    void clear() { m_markers.clear(); }

    // In time order; the oldest are dropped beyond the bound (memory stays bounded).
    const std::deque<SampleMarker> &markers() const { return m_markers; }
    std::vector<SampleMarker> markersIn(double t0, double t1) const;

private:
    qsizetype m_maxMarkers;
    std::deque<SampleMarker> m_markers;
};

} // namespace vt::model
