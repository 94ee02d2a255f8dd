#include "sim/plant_errors.h"

#include "dict/dictionary.h"

namespace vt::dev::sim {

ErrorTable errorTableFor(const Dictionary &dict)
{
    return dict.family.rfind("opat", 0) == 0 ? ErrorTable::Opat : ErrorTable::Dma;
}

std::optional<int> errorNumber(PlantError error, ErrorTable table, int branch)
{
    const bool second = branch == 2;
    if (table == ErrorTable::Dma) {
        switch (error) {
        case PlantError::SetValueWireBreak: return 2;
        case PlantError::SetValueWireBreak2: return 4;
        case PlantError::SetValueOverCurrent: return 5;
        case PlantError::SetValueOverCurrent2: return 6;
        case PlantError::OutputShortCircuit: return 3;
        case PlantError::OutputCurrentDeviation: return 8;
        case PlantError::FeedbackCableFracture:
        case PlantError::FeedbackOverload: return 1;
        case PlantError::Count: break;
        }
        return std::nullopt;
    }
    switch (error) {
    case PlantError::SetValueWireBreak:
    case PlantError::SetValueWireBreak2: return 9;
    case PlantError::FeedbackCableFracture: return second ? 4 : 2;
    case PlantError::FeedbackOverload: return second ? 6 : 5;
    case PlantError::OutputShortCircuit:
    case PlantError::OutputCurrentDeviation: return 8;
    case PlantError::SetValueOverCurrent:
    case PlantError::SetValueOverCurrent2:
    case PlantError::Count: break;
    }
    return std::nullopt;
}

const char *errorKey(PlantError error)
{
    switch (error) {
    case PlantError::SetValueWireBreak: return "set-value-wire-break";
    case PlantError::SetValueWireBreak2: return "set-value-wire-break-2";
    case PlantError::SetValueOverCurrent: return "set-value-over-current";
    case PlantError::SetValueOverCurrent2: return "set-value-over-current-2";
    case PlantError::FeedbackCableFracture: return "feedback-cable-fracture";
    case PlantError::FeedbackOverload: return "feedback-overload";
    case PlantError::OutputShortCircuit: return "output-short-circuit";
    case PlantError::OutputCurrentDeviation: return "output-current-deviation";
    case PlantError::Count: break;
    }
    return "?";
}

std::optional<int> PlantErrors::reportedNumber(ErrorTable table, int branch) const
{
    std::optional<int> lowest;
    for (unsigned i = 0; i < static_cast<unsigned>(PlantError::Count); ++i) {
        const auto e = static_cast<PlantError>(i);
        if (!test(e))
            continue;
        const auto n = errorNumber(e, table, branch);
        if (n && (!lowest || *n < *lowest))
            lowest = n;
    }
    return lowest;
}

std::string PlantErrors::text() const
{
    std::string out;
    for (unsigned i = 0; i < static_cast<unsigned>(PlantError::Count); ++i) {
        const auto e = static_cast<PlantError>(i);
        if (!test(e))
            continue;
        if (!out.empty())
            out += ", ";
        out += errorKey(e);
    }
    return out;
}

void ErrorLatch::update(const PlantErrors &present)
{
    m_present = present;
    m_latched |= present;
}

bool ErrorLatch::acknowledge()
{
    m_latched = m_present;
    return !m_latched.any();
}

} // namespace vt::dev::sim
