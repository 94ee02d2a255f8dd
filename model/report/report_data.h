// The commissioning report's input data that comes from elsewhere: the header the person fills in,
// the session's write log and the drift against a reference fingerprint. Plain values with Qt Core
// types; whoever makes a report fills them (the GUI from QSettings and the session, the CLI from
// its options) and the renderers show whatever is given — an empty write log says so, an empty
// drift leaves its section out. Any thread, one at a time.
#pragma once

#include <QDateTime>
#include <QString>
#include <vector>

namespace vt::model {

// Filled in once by the person and remembered (the GUI keeps it in QSettings).
struct ReportHeader
{
    QString customer;
    QString machine;
    QString axis;
    QString operatorName;
    QString comment;

    bool operator==(const ReportHeader &) const = default;
};

// One write the tool made: the parameter, old → new as a person reads them, and how it ended.
struct ReportWrite
{
    QDateTime time;
    int module = 0;
    QString row;  // dictionary name, "C1.07"
    QString name; // label for people
    QString unit;
    QString oldText;
    QString newText;
    QString status; // writeStatusKey() (model/session/write_record.h): "verified", "refused", …
    QString reasonEn;
    QString reasonDe; // the device's or the tool's reason, empty when there is none
};

// A setting that differs from the reference fingerprint.
struct ReportDriftParam
{
    int module = 0;
    QString row;
    QString name;
    QString reference;
    QString now;
    QString unit;
};

// A step-test figure measured again and compared with the reference's.
struct ReportDriftMetric
{
    int module = 0;
    QString test;   // "step up 3 → 5 V"
    QString metric; // label for people, "rise time"
    double reference = 0;
    double now = 0;
    QString unit;
    double deltaPercent = 0;
    double thresholdPercent = 0;
    bool exceeded = false;
};

// The reference's and today's response of one test, on one time axis, for an overlay plot.
struct ReportDriftCurve
{
    int module = 0;
    QString test;
    QString unit;
    std::vector<double> time; // s
    std::vector<double> reference;
    std::vector<double> now;
};

struct ReportDrift
{
    QString referenceFile;
    QDateTime takenAt;
    std::vector<ReportDriftParam> params;
    std::vector<ReportDriftMetric> metrics;
    std::vector<ReportDriftCurve> curves;

    bool empty() const
    {
        return referenceFile.isEmpty() && params.empty() && metrics.empty() && curves.empty();
    }
};

} // namespace vt::model
