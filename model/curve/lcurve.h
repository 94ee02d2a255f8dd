// LCurve: the linearisation curves (L block) of an HCS module found in its dictionary — points
// as pairs of rows Lb.xi / Lb.yi, which coordinates the device fixes and why, and where an
// edited point may go (row range, x order). Plain data over immutable dictionary rows.
#pragma once

#include "core/local_text.h"
#include "dict/dictionary.h"

#include <QString>
#include <optional>
#include <string>
#include <vector>

namespace vt::model {

enum class LAxis { X, Y };

// Why a coordinate cannot be edited.
enum class LFixedBy {
    None,
    Device,   // the device fixes it: min = max, "fixed value"
    ReadOnly, // the row is read-only
    Inactive, // the row is not active (or not implemented) on this device
};

// One coordinate of a point: its dictionary row and limits in display units.
struct LCoordinate
{
    const dev::ParamMeta *row = nullptr; // points into the dictionary, which outlives the curve
    double min = 0;
    double max = 0;
    double step = 1;  // one raw step in display units (0.001 V)
    int decimals = 0; // display decimals
    // Set when the coordinate cannot be edited; fixedText() says why.
    LFixedBy fixedBy = LFixedBy::None;

    bool fixed() const { return fixedBy != LFixedBy::None; }
};

// Why `coord` cannot be edited, a sentence that names the row (a fixed value in `lang`'s number
// format); empty when it can be.
QString fixedText(const LCoordinate &coord, dev::Language lang);

struct LPoint
{
    LCoordinate x; // input (set value) coordinate
    LCoordinate y; // output coordinate
};

struct LCurve
{
    int branch = 0;             // 1 or 2
    std::string name;           // "L1"
    std::string unit;           // of the x rows ("V")
    std::vector<LPoint> points; // point i is rows Lb.xi / Lb.yi
    // Cb.02 "Linearization": selects whether / which curve the branch uses (OPAT: 6 = customer
    // curve).
    const dev::ParamMeta *selector = nullptr;
};

// The curves of a dictionary for one software version and mode (empty strings: any). A curve
// ends at the first point whose x or y row is missing or does not apply; curves without points
// are left out (DMA Profibus dictionaries have no L block).
std::vector<LCurve> findLCurves(const dev::Dictionary &dictionary, const std::string &version,
                                const std::string &mode);

// Current display values of one point; nullopt: not known (not read, no file value).
struct LPointValue
{
    std::optional<double> x;
    std::optional<double> y;
};

struct LRange
{
    double min = 0;
    double max = 0;

    bool empty() const { return min > max; }
    double clamp(double v) const { return v < min ? min : (v > max ? max : v); }
};

const LCoordinate &coordinate(const LPoint &point, LAxis axis);

// Display value on the row's raster (0.0014 -> 0.001 for a milli scale).
double snapToStep(const LCoordinate &coord, double display);

// Where a coordinate may go: the row's range; for x narrowed to lie strictly between the
// neighbours' known x (at least one raw step apart). Empty when the neighbours leave no room.
LRange allowedRange(const LCurve &curve, const std::vector<LPointValue> &values, int index,
                    LAxis axis);

// nullopt when coordinate `axis` of point `index` may take `display`; otherwise why not (names the
// row and the limit; numbers in `lang`'s format). A fixed coordinate refuses any value but its
// current one.
std::optional<QString> checkCoordinate(const LCurve &curve, const std::vector<LPointValue> &values,
                                       int index, LAxis axis, double display,
                                       dev::Language lang = dev::Language::English);

} // namespace vt::model
