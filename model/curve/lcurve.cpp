#include "lcurve.h"

#include "dict/cooking.h"

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

std::optional<dev::LocalText> whyFixed(const dev::ParamMeta &meta)
{
    switch (meta.access) {
    case dev::Access::Read:
        return dev::LocalText{meta.name + " is read-only", meta.name + " ist schreibgeschützt"};
    case dev::Access::Inactive:
    case dev::Access::NotImplemented:
        return dev::LocalText{meta.name + " is not active on this device",
                              meta.name + " ist in diesem Gerät nicht aktiv"};
    case dev::Access::ReadWrite:
    case dev::Access::Write: break;
    }
    // DMA Profinet manual §6 and OPAT manual, list of parameters: L1.x0 / L2.x0 (and on the
    // OPAT L1.x8 / L2.x8) have min = max, "(fixed value)".
    if (meta.min == meta.max) {
        const std::string en = dev::formatValue(meta, meta.min, dev::Language::English);
        const std::string de = dev::formatValue(meta, meta.min, dev::Language::German);
        return dev::LocalText{meta.name + " is fixed by the device at " + en,
                              meta.name + " ist vom Gerät fest auf " + de + " gesetzt"};
    }
    return std::nullopt;
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
    c.fixedBecause = whyFixed(meta);
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

std::optional<dev::LocalText> checkCoordinate(const LCurve &curve,
                                              const std::vector<LPointValue> &values, int index,
                                              LAxis axis, double display)
{
    if (index < 0 || index >= static_cast<int>(curve.points.size()))
        return dev::LocalText{curve.name + " has no point " + std::to_string(index),
                              curve.name + " hat keinen Punkt " + std::to_string(index)};
    const auto i = static_cast<std::size_t>(index);
    const LCoordinate &c = coordinate(curve.points[i], axis);
    const dev::ParamMeta &meta = *c.row;
    if (!std::isfinite(display))
        return dev::LocalText{meta.name + ": not a number", meta.name + ": keine Zahl"};
    if (c.fixed()) {
        std::optional<double> current;
        if (i < values.size())
            current = axis == LAxis::X ? values[i].x : values[i].y;
        if (current && sameOnRaster(c, *current, display))
            return std::nullopt; // unchanged
        return c.fixedBecause;
    }
    if (auto err = dev::checkRange(meta, toRaw(meta, display)))
        return err->message;
    if (axis == LAxis::Y)
        return std::nullopt;
    const LRange range = allowedRange(curve, values, index, axis);
    if (display < range.min - c.step / 2 && index > 0) {
        const dev::ParamMeta &prev = *curve.points[i - 1].x.row;
        const double prevX = *values[i - 1].x;
        return dev::LocalText{meta.name + " must be above " + prev.name + " (" +
                                  formatDisplay(prev, prevX, dev::Language::English) + ")",
                              meta.name + " muss größer als " + prev.name + " (" +
                                  formatDisplay(prev, prevX, dev::Language::German) + ") sein"};
    }
    if (display > range.max + c.step / 2 && i + 1 < curve.points.size()) {
        const dev::ParamMeta &next = *curve.points[i + 1].x.row;
        const double nextX = *values[i + 1].x;
        return dev::LocalText{meta.name + " must be below " + next.name + " (" +
                                  formatDisplay(next, nextX, dev::Language::English) + ")",
                              meta.name + " muss kleiner als " + next.name + " (" +
                                  formatDisplay(next, nextX, dev::Language::German) + ") sein"};
    }
    return std::nullopt;
}

} // namespace vt::model
