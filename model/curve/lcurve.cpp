#include "lcurve.h"

#include "dict/cooking.h"

#include <QCoreApplication>
#include <cmath>

namespace vt::model {
namespace {

// Points per curve in every HCS dictionary (x0..x8); the search stops earlier at a missing row.
constexpr int kMaxPoints = 9;

double displayStep(const dev::ParamMeta &meta)
{
    const double step = meta.step > 0 ? meta.step : 1.0;
    return meta.scale.name.empty() ? step : step * meta.scale.factor;
}

int displayDecimals(const dev::ParamMeta &meta)
{
    if (meta.scale.name.empty())
        return meta.isFloat() ? 3 : 0;
    return meta.scale.decimals;
}

double toRaw(const dev::ParamMeta &meta, double display)
{
    return meta.scale.name.empty() || meta.scale.factor == 0
               ? display
               : std::round(display / meta.scale.factor);
}

std::string formatDisplay(const dev::ParamMeta &meta, double display, dev::Language lang)
{
    return dev::formatValue(meta, toRaw(meta, display), lang);
}

LFixedBy whyFixed(const dev::ParamMeta &meta)
{
    switch (meta.access) {
    case dev::Access::Read: return LFixedBy::ReadOnly;
    case dev::Access::Inactive:
    case dev::Access::NotImplemented: return LFixedBy::Inactive;
    case dev::Access::ReadWrite:
    case dev::Access::Write: break;
    }
    // DMA Profinet manual §6 and OPAT manual, list of parameters: L1.x0 / L2.x0 (and on the
    // OPAT L1.x8 / L2.x8) have min = max, "(fixed value)".
    return meta.min == meta.max ? LFixedBy::Device : LFixedBy::None;
}

QString qs(const std::string &text)
{
    return QString::fromStdString(text);
}

LCoordinate makeCoordinate(const dev::ParamMeta &meta)
{
    LCoordinate c;
    c.row = &meta;
    const dev::Limits limits = dev::rowLimits(meta);
    c.min = dev::toDisplay(meta, limits.min);
    c.max = dev::toDisplay(meta, limits.max);
    c.step = displayStep(meta);
    c.decimals = displayDecimals(meta);
    c.fixedBy = whyFixed(meta);
    return c;
}

const dev::ParamMeta *applicableRow(const dev::Dictionary &dictionary, const std::string &name,
                                    const std::string &version, const std::string &mode)
{
    const dev::ParamMeta *meta = dictionary.find(name);
    return meta && meta->appliesTo(version, mode) && !meta->isString() ? meta : nullptr;
}

bool sameOnRaster(const LCoordinate &c, double a, double b)
{
    return std::abs(a - b) < c.step / 2;
}

} // namespace

std::vector<LCurve> findLCurves(const dev::Dictionary &dictionary, const std::string &version,
                                const std::string &mode)
{
    std::vector<LCurve> curves;
    for (int branch = 1; branch <= 2; ++branch) {
        LCurve curve;
        curve.branch = branch;
        curve.name = "L" + std::to_string(branch);
        for (int i = 0; i < kMaxPoints; ++i) {
            const std::string suffix = std::to_string(i);
            const dev::ParamMeta *x =
                applicableRow(dictionary, curve.name + ".x" + suffix, version, mode);
            const dev::ParamMeta *y =
                applicableRow(dictionary, curve.name + ".y" + suffix, version, mode);
            if (!x || !y)
                break;
            curve.points.push_back({makeCoordinate(*x), makeCoordinate(*y)});
        }
        if (curve.points.empty())
            continue;
        curve.unit = curve.points.front().x.row->unit;
        curve.selector =
            applicableRow(dictionary, "C" + std::to_string(branch) + ".02", version, mode);
        curves.push_back(std::move(curve));
    }
    return curves;
}

const LCoordinate &coordinate(const LPoint &point, LAxis axis)
{
    return axis == LAxis::X ? point.x : point.y;
}

double snapToStep(const LCoordinate &coord, double display)
{
    if (!std::isfinite(display) || coord.step <= 0)
        return display;
    const double snapped = std::round(display / coord.step) * coord.step;
    const double p = std::pow(10.0, coord.decimals);
    return std::round(snapped * p) / p; // no 0.30000000000000004 in the table
}

LRange allowedRange(const LCurve &curve, const std::vector<LPointValue> &values, int index,
                    LAxis axis)
{
    if (index < 0 || index >= static_cast<int>(curve.points.size()))
        return {1, 0};
    const LCoordinate &c = coordinate(curve.points[static_cast<std::size_t>(index)], axis);
    LRange range{c.min, c.max};
    if (axis == LAxis::Y)
        return range;
    // The module interpolates between neighbouring points, so x has to rise from point to point.
    // The manuals do not say whether equal x are accepted; we require one raw step between them.
    const auto valueAt = [&](int i) -> std::optional<double> {
        if (i < 0 || i >= static_cast<int>(values.size()) ||
            i >= static_cast<int>(curve.points.size()))
            return std::nullopt;
        return values[static_cast<std::size_t>(i)].x;
    };
    if (const auto prev = valueAt(index - 1))
        range.min = std::max(range.min, snapToStep(c, *prev + c.step));
    if (const auto next = valueAt(index + 1))
        range.max = std::min(range.max, snapToStep(c, *next - c.step));
    return range;
}

QString fixedText(const LCoordinate &coord, dev::Language lang)
{
    const QString name = coord.row ? qs(coord.row->name) : QString();
    switch (coord.fixedBy) {
    case LFixedBy::None: return {};
    case LFixedBy::ReadOnly:
        return QCoreApplication::translate("vt::model::LCurve", "%1 is read-only").arg(name);
    case LFixedBy::Inactive:
        return QCoreApplication::translate("vt::model::LCurve", "%1 is not active on this device")
            .arg(name);
    case LFixedBy::Device:
        return QCoreApplication::translate("vt::model::LCurve", "%1 is fixed by the device at %2")
            .arg(name, qs(dev::formatValue(*coord.row, coord.row->min, lang)));
    }
    return {};
}

std::optional<QString> checkCoordinate(const LCurve &curve, const std::vector<LPointValue> &values,
                                       int index, LAxis axis, double display, dev::Language lang)
{
    if (index < 0 || index >= static_cast<int>(curve.points.size()))
        return QCoreApplication::translate("vt::model::LCurve", "%1 has no point %2")
            .arg(qs(curve.name))
            .arg(index);
    const auto i = static_cast<std::size_t>(index);
    const LCoordinate &c = coordinate(curve.points[i], axis);
    const dev::ParamMeta &meta = *c.row;
    if (!std::isfinite(display))
        return QCoreApplication::translate("vt::model::LCurve", "%1: not a number")
            .arg(qs(meta.name));
    if (c.fixed()) {
        std::optional<double> current;
        if (i < values.size())
            current = axis == LAxis::X ? values[i].x : values[i].y;
        if (current && sameOnRaster(c, *current, display))
            return std::nullopt; // unchanged
        return fixedText(c, lang);
    }
    if (auto err = dev::checkRange(meta, toRaw(meta, display)))
        return qs(err->message.in(lang));
    if (axis == LAxis::Y)
        return std::nullopt;
    const LRange range = allowedRange(curve, values, index, axis);
    if (display < range.min - c.step / 2 && index > 0) {
        const dev::ParamMeta &prev = *curve.points[i - 1].x.row;
        return QCoreApplication::translate("vt::model::LCurve", "%1 must be above %2 (%3)")
            .arg(qs(meta.name), qs(prev.name), qs(formatDisplay(prev, *values[i - 1].x, lang)));
    }
    if (display > range.max + c.step / 2 && i + 1 < curve.points.size()) {
        const dev::ParamMeta &next = *curve.points[i + 1].x.row;
        return QCoreApplication::translate("vt::model::LCurve", "%1 must be below %2 (%3)")
            .arg(qs(meta.name), qs(next.name), qs(formatDisplay(next, *values[i + 1].x, lang)));
    }
    return std::nullopt;
}

} // namespace vt::model
