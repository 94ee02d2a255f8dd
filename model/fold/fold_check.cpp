#include "fold_check.h"

#include "dict/dictionary.h"
#include "dict/dictionary_loader.h"
#include "hcs/cmd15.h"
#include "plc_config.h"

#include <algorithm>
#include <map>
#include <set>

namespace vt::model {

namespace {

using dev::LocalText;

template<typename T> LocalText num(T value)
{
    return dev::same(std::to_string(value));
}

// With the version unknown, the mode (or the family's worked example) picks the dictionary.
int effectiveVersion(FoldNode node, std::size_t index, const FoldModule &m)
{
    if (m.version != 0)
        return m.version;
    switch (node) {
    case FoldNode::Opat: return index == 0 ? 34 : 31;
    case FoldNode::DmaProfibus: return m.mode == 2 ? 22 : (m.mode >= 3 ? 32 : 15);
    case FoldNode::DmaProfinet: return m.mode >= 3 ? 51 : 13;
    }
    return 0;
}

class Checker
{
public:
    Checker(const FoldPlan &plan, const dev::DictionarySet *set) : m_plan(plan), m_set(set) {}

    std::vector<FoldFinding> run()
    {
        checkCount();
        checkProductNumber();
        checkAddresses();
        checkSnum();
        checkModes();
        for (std::size_t i = 0; i < m_plan.modules.size(); ++i)
            checkOptions(i);
        checkCanBaud();
        std::stable_sort(
            m_out.begin(), m_out.end(),
            [](const FoldFinding &a, const FoldFinding &b) { return a.module < b.module; });
        return m_out;
    }

private:
    void add(FoldSeverity s, FoldCheckCode c, int module, std::string param,
             std::vector<FoldSentence> sentences)
    {
        m_out.push_back({s, c, module, std::move(param), std::move(sentences)});
    }
    void add(FoldSeverity s, FoldCheckCode c, int module, std::string param, FoldText text,
             std::vector<FoldArg> args = {})
    {
        add(s, c, module, std::move(param), {FoldSentence{text, std::move(args)}});
    }
    // A sentence about module i ("Module %1 (%2): …"): its number and address come first.
    void addAbout(FoldSeverity s, FoldCheckCode c, std::size_t i, std::string param, FoldText text,
                  std::vector<FoldArg> more = {})
    {
        std::vector<FoldArg> args{num(i + 1), foldAddress(m_plan.node, m_plan.modules[i])};
        args.insert(args.end(), more.begin(), more.end());
        add(s, c, static_cast<int>(i), std::move(param), text, std::move(args));
    }
    bool opat() const { return m_plan.node == FoldNode::Opat; }

    void checkCount()
    {
        const std::size_t n = m_plan.modules.size();
        if (n == 0) {
            add(FoldSeverity::Error, FoldCheckCode::NoModules, -1, {}, FoldText::NoModules);
            return;
        }
        if (n > foldMaxModules(m_plan.node)) {
            add(FoldSeverity::Error, FoldCheckCode::TooManyModules, -1, {},
                opat() ? FoldText::TooManyOpat : FoldText::TooManyDma, {num(n)});
            return;
        }
        if (!opat() && n > foldMaxCmd15Modules(m_plan.node))
            add(FoldSeverity::Error, FoldCheckCode::Cmd15Limit, -1, {}, FoldText::Cmd15Limit,
                {num(n)});
    }

    void checkProductNumber()
    {
        if (m_plan.node != FoldNode::DmaProfibus || m_plan.modules.empty())
            return;
        const GsdChoice g = chooseGsd(m_plan.node, m_plan.modules.size(), m_plan.productNumber);
        if (g.productNumberDecided)
            return;
        if (m_plan.productNumber.empty())
            add(FoldSeverity::Info, FoldCheckCode::ProductNumber, -1, {},
                FoldText::ProductNumberMissing);
        else
            add(FoldSeverity::Warning, FoldCheckCode::ProductNumber, -1, {},
                FoldText::ProductNumberUndecided, {dev::same(m_plan.productNumber)});
    }

    void checkAddresses()
    {
        const std::size_t n = m_plan.modules.size();
        std::map<int, std::vector<std::size_t>> byAddress;
        bool allInRange = true;
        for (std::size_t i = 0; i < n; ++i) {
            const FoldModule &m = m_plan.modules[i];
            byAddress[m.address].push_back(i);
            if (opat()) {
                if (i == 0 && m.address != 0) {
                    add(FoldSeverity::Error, FoldCheckCode::AddressOrder, static_cast<int>(i),
                        "SADR", FoldText::OpatMasterSadr);
                    allInRange = false;
                } else if (i > 0 && (m.address < 1 || m.address > 7)) {
                    addAbout(FoldSeverity::Error, FoldCheckCode::AddressOutOfRange, i, "SADR",
                             FoldText::OpatSlaveSwitch);
                    allInRange = false;
                }
                continue;
            }
            // DMA: E22 range from the dictionary (0 = no bus function … 32).
            if (m.address < 1 || m.address > 32) {
                addAbout(FoldSeverity::Error, FoldCheckCode::AddressOutOfRange, i, "E22",
                         m.address == 0 ? FoldText::E22Off : FoldText::E22Range);
                allInRange = false;
            } else if (m.address > 5) {
                addAbout(FoldSeverity::Error, FoldCheckCode::AddressBeyondCmd15, i, "E22",
                         FoldText::E22BeyondCmd15);
                allInRange = false;
            }
        }
        for (const auto &[address, indices] : byAddress) {
            if (indices.size() < 2)
                continue;
            std::string list;
            for (std::size_t k : indices)
                list += (list.empty() ? "" : ", ") + std::to_string(k + 1);
            add(FoldSeverity::Error, FoldCheckCode::DuplicateAddress, static_cast<int>(indices[1]),
                opat() ? "SADR" : "E22", opat() ? FoldText::DuplicateSadr : FoldText::DuplicateE22,
                {dev::same(list), num(address)});
            allInRange = false;
        }
        if (!allInRange || n == 0 || n > foldMaxCmd15Modules(m_plan.node))
            return;
        // CMD 15 block x goes to the module with address x, SNUM covers 1 … n (0 … n−1 on OPAT).
        const int base = opat() ? 0 : 1;
        bool gap = false, rising = true;
        for (std::size_t i = 0; i < n; ++i) {
            const int a = m_plan.modules[i].address;
            if (a - base >= static_cast<int>(n))
                gap = true;
            if (a != base + static_cast<int>(i))
                rising = false;
        }
        if (gap)
            add(FoldSeverity::Error, FoldCheckCode::AddressOrder, -1, opat() ? "SADR" : "E22",
                FoldText::AddressGap, {num(n), num(base), num(base + static_cast<int>(n) - 1)});
        else if (!rising)
            add(FoldSeverity::Warning, FoldCheckCode::AddressOrder, -1, opat() ? "SADR" : "E22",
                opat() ? FoldText::OpatSwitchOrder : FoldText::DmaE22Order);
    }

    void checkSnum()
    {
        if (!m_plan.plcSnum || m_plan.modules.empty())
            return;
        const auto family = foldFamily(m_plan.node);
        const auto want = dev::hcs::snumForModules(family, m_plan.modules.size());
        const int have = *m_plan.plcSnum;
        if (want && have == *want)
            return;
        const LocalText w = want ? num(*want) : dev::same("-");
        const auto max = dev::hcs::maxCyclicModules(family);
        const bool invalid = !dev::hcs::modulesForSnum(
                                 family, static_cast<std::uint8_t>(std::clamp(have, 0, 255))) ||
                             have < 0 || have > 255;
        std::vector<FoldSentence> sentences{{opat() ? FoldText::SnumOpat : FoldText::SnumDma,
                                             {num(have), num(m_plan.modules.size()), w}}};
        if (invalid)
            sentences.push_back({FoldText::SnumRange, {dev::same(opat() ? "0 … 7" : "1 … 5")}});
        else if (want && have > *want)
            sentences.push_back({FoldText::SnumWaits, {}});
        else
            sentences.push_back({FoldText::SnumBeyond, {}});
        sentences.push_back({FoldText::SnumLength, {num(3 + 5 * max)}});
        add(FoldSeverity::Error, FoldCheckCode::SnumMismatch, -1, "SNUM", std::move(sentences));
    }

    void checkModes()
    {
        std::set<int> profiles;
        for (std::size_t i = 0; i < m_plan.modules.size(); ++i) {
            const FoldModule &m = m_plan.modules[i];
            const std::vector<int> versions = foldVersions(m_plan.node, i);
            if (m.version == 0) {
                addAbout(FoldSeverity::Info, FoldCheckCode::UnknownVersion, i, "Vers",
                         FoldText::VersionUnknown);
            } else if (std::find(versions.begin(), versions.end(), m.version) == versions.end()) {
                std::string list;
                for (int v : versions)
                    list += (list.empty() ? "V" : ", V") + std::to_string(v);
                addAbout(FoldSeverity::Error, FoldCheckCode::UnknownVersion, i, "Vers",
                         FoldText::VersionNotHere, {num(m.version), dev::same(list)});
                continue;
            }
            const auto profile = foldProfile(m_plan.node, m);
            if (!profile) {
                addAbout(FoldSeverity::Error, FoldCheckCode::UnknownLayout, i, "E00",
                         FoldText::NoLayout, {num(m.version), num(m.mode)});
                continue;
            }
            profiles.insert(static_cast<int>(*profile));
        }
        if (profiles.size() > 1)
            add(FoldSeverity::Warning, FoldCheckCode::MixedModes, -1, "E00", FoldText::MixedModes);
    }

    const dev::Dictionary *dictionaryFor(std::size_t i) const
    {
        if (!m_set)
            return nullptr;
        FoldModule m = m_plan.modules[i];
        m.version = effectiveVersion(m_plan.node, i, m);
        return foldDictionary(*m_set, m_plan.node, m);
    }

    void checkOptions(std::size_t i)
    {
        const FoldModule &m = m_plan.modules[i];
        const std::vector<std::string> allowed = foldOptionNames(m_plan.node, i);
        const dev::Dictionary *dict = dictionaryFor(i);
        const int version = effectiveVersion(m_plan.node, i, m);
        for (const char *name : {"E17", "E23", "E24", "E26", "E28"}) {
            const std::optional<int> value = foldOption(m.options, name);
            if (!value)
                continue;
            if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
                addAbout(FoldSeverity::Warning, FoldCheckCode::OptionNotApplicable, i, name,
                         FoldText::OptionNotBus, {dev::same(name)});
                continue;
            }
            const dev::ParamMeta *meta = dict ? dict->find(name) : nullptr;
            if (meta && !meta->appliesTo(std::to_string(version), "")) {
                addAbout(FoldSeverity::Warning, FoldCheckCode::OptionNotApplicable, i, name,
                         FoldText::OptionNotInVersion, {dev::same(name), num(version)});
                continue;
            }
            if (meta && (*value < meta->min || *value > meta->max)) {
                addAbout(FoldSeverity::Error, FoldCheckCode::OptionOutOfRange, i, name,
                         FoldText::OptionOutOfRange,
                         {dev::same(name), num(*value), num(static_cast<long long>(meta->min)),
                          num(static_cast<long long>(meta->max)), meta->label});
                continue;
            }
            consequence(i, name, *value);
        }
    }

    void consequence(std::size_t i, const std::string &name, int value)
    {
        const int idx = static_cast<int>(i);
        if (name == "E24") {
            if (value == 126)
                add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, idx, name,
                    FoldText::E24Master);
            else
                add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, idx, name,
                    FoldText::E24Address, {num(value)});
        } else if (name == "E28") {
            // OPAT manual §5.7: behaviour of the master when a CAN slave is lost.
            static const FoldText kText[] = {FoldText::E28Stop, FoldText::E28Flag,
                                             FoldText::E28Ignore};
            add(value == 2 ? FoldSeverity::Warning : FoldSeverity::Info,
                FoldCheckCode::OptionConsequence, idx, name, kText[std::clamp(value, 0, 2)]);
        } else if (name == "E23" && value == 0) {
            addAbout(FoldSeverity::Info, FoldCheckCode::OptionConsequence, i, name,
                     FoldText::E23Off);
        } else if (name == "E17" && value == 0) {
            addAbout(FoldSeverity::Info, FoldCheckCode::OptionConsequence, i, name,
                     FoldText::E17Analogue);
        } else if (name == "E26") {
            if (value == 0 && m_plan.modules.size() > 1)
                addAbout(FoldSeverity::Error, FoldCheckCode::OptionConsequence, i, name,
                         FoldText::E26Off);
        }
    }

    // Every OPAT module on the CAN bus must use the same baud rate; a change set through PROFIBUS
    // takes effect only after a reboot (OPAT manual §7, E26).
    void checkCanBaud()
    {
        if (!opat())
            return;
        std::set<int> rates;
        bool any = false;
        for (const FoldModule &m : m_plan.modules)
            if (m.options.e26) {
                rates.insert(*m.options.e26);
                any = true;
            }
        if (rates.size() > 1)
            add(FoldSeverity::Error, FoldCheckCode::OptionConsequence, -1, "E26",
                FoldText::CanBaudDiffers);
        else if (any)
            add(FoldSeverity::Info, FoldCheckCode::OptionConsequence, -1, "E26",
                FoldText::CanBaudReboot);
    }

    const FoldPlan &m_plan;
    const dev::DictionarySet *m_set;
    std::vector<FoldFinding> m_out;
};

} // namespace

std::vector<FoldFinding> checkFoldPlan(const FoldPlan &plan, const dev::DictionarySet *dictionaries)
{
    if (!dictionaries) {
        const auto &builtin = dev::builtinDictionaries();
        dictionaries = builtin.ok() ? &*builtin : nullptr;
    }
    return Checker(plan, dictionaries).run();
}

bool hasErrors(const std::vector<FoldFinding> &findings)
{
    return std::any_of(findings.begin(), findings.end(),
                       [](const FoldFinding &f) { return f.severity == FoldSeverity::Error; });
}

std::string_view foldSeverityKey(FoldSeverity severity)
{
    switch (severity) {
    case FoldSeverity::Info: return "info";
    case FoldSeverity::Warning: return "warning";
    case FoldSeverity::Error: return "error";
    }
    return "info";
}

} // namespace vt::model
