#include "confirm_gate.h"

#include <algorithm>
#include <istream>
#include <map>

namespace vt::cli {

namespace {

std::string change(const GateItem &item, dev::Language lang)
{
    return item.row->name + " " +
           (item.before ? displayOf(*item.row, *item.before, lang) : std::string("(unknown)")) +
           " -> " + displayOf(*item.row, item.value, lang);
}

bool isYes(std::string answer)
{
    std::erase_if(answer, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
    std::transform(answer.begin(), answer.end(), answer.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    // German speakers answer "j"/"ja" (valvetune-cli --lang de shows German values).
    return answer == "y" || answer == "yes" || answer == "j" || answer == "ja";
}

// What the device holds now for the rows the caller did not read; rows that do not answer stay
// unknown and are shown so.
void readBefore(DeviceRun &run, std::vector<GateItem> &items)
{
    std::map<int, std::vector<const dev::ParamMeta *>> unknown;
    for (const GateItem &item : items)
        if (!item.before && item.row->readable())
            unknown[item.module->address].push_back(item.row);
    for (const auto &[address, rows] : unknown) {
        const auto result = run.read(address, rows);
        if (!result)
            continue;
        for (const model::RowValue &v : result->values)
            for (GateItem &item : items)
                if (item.module->address == address && item.row == v.row)
                    item.before = v.value;
    }
}

} // namespace

ConfirmGate::ConfirmGate(Context &ctx, QStringList &args)
    : m_ctx(ctx), m_yes(takeFlag(args, QStringLiteral("--yes")))
{
}

int ConfirmGate::pass(DeviceRun &run, const model::ModuleInfo &module,
                      const std::vector<model::WriteItem> &items)
{
    std::vector<GateItem> gated;
    for (const model::WriteItem &item : items)
        gated.push_back({&module, item.row, item.value, item.before});
    return pass(run, std::move(gated));
}

int ConfirmGate::pass(DeviceRun &run, std::vector<GateItem> items)
{
    return pass(run, std::move(items), {});
}

int ConfirmGate::pass(DeviceRun &run, std::vector<GateItem> items, const std::string &what)
{
    std::erase_if(items, [](const GateItem &item) { return !item.row->movesActuator; });
    if (m_yes || items.empty())
        return kExitOk;
    readBefore(run, items);
    // A value the device already holds is not sent again (the write sends changes only). A
    // test's set value (its first items) is listed whatever the device holds: the signal writes
    // more than that value.
    const dev::ParamMeta *testRow = what.empty() ? nullptr : items.front().row;
    std::erase_if(items, [&](const GateItem &item) {
        return item.row != testRow && item.before && sameValue(*item.row, item.value, *item.before);
    });
    if (items.empty())
        return kExitOk;

    const dev::Language lang = run.lang();
    if (!m_ctx.console.terminal || !m_ctx.console.in) {
        std::string list;
        for (const GateItem &item : items)
            list +=
                (list.empty() ? "" : "; ") + moduleText(*item.module) + ": " + change(item, lang);
        return m_ctx.fail(kExitUsage, (what.empty() ? "this write" : what) +
                                          " can move the actuator (" + list +
                                          "); there is no terminal to confirm it: pass --yes "
                                          "to write it anyway; nothing was sent");
    }
    if (!what.empty())
        m_ctx.err << "This " << what.substr(2) << ".\n";
    m_ctx.err << "This write can move the actuator:\n";
    for (const GateItem &item : items)
        m_ctx.err << "  " << moduleText(*item.module) << ": " << change(item, lang) << '\n';
    m_ctx.err << "Write " << (items.size() == 1 ? "it" : "them") << "? [y/N] " << std::flush;
    std::string answer;
    if (!std::getline(*m_ctx.console.in, answer) || !isYes(answer))
        return m_ctx.fail(kExitUsage, "not confirmed; nothing was sent");
    return kExitOk;
}

} // namespace vt::cli
