// The one simulator fixture of the Qt tests: a model::Connection to the built-in simulator, built
// as the product builds it (SimLink, behind a FaultLink when faults are asked for, the protocol
// adapter, Session, DeviceAccess) and opened with a bounded wait; connectSim() also identifies
// every module, as the main window does before it hands the connection on.
// The test owns the rig; GUI thread only.
#pragma once

#include "access/hcs_rows.h"
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/session/connection.h"
#include "qt_printers.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"
#include "test_wait.h"
#include "transports/fault_link.h"
#include "transports/fault_spec.h"

#include <QSignalSpy>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vt::test {

inline const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}

// What to simulate and how to reach it.
struct SimSetup
{
    std::string family;      // "opat", "dma-pn-v51", "wandfluh-sd7" …
    std::size_t modules = 1; // HCS node size
    std::string protocol;    // a dev::LinkProtocol key; "" = the simulator's default for the family
    std::optional<link::FaultSpec> fault;         // the link behind a FaultLink
    std::optional<model::SessionOptions> options; // instead of those the connection picks
    // The bare dictionary defaults instead of the commissioned machine (`--factory`), for the
    // tests about a module's defaults (E17 = 0, C1.09 = 0 …).
    bool factory = false;
};

struct SimRig
{
    std::unique_ptr<model::Connection> connection;
    std::vector<model::ModuleInfo> modules; // filled by identify()

    model::Session &session() const { return connection->session(); }
    model::DeviceAccess &access() const { return connection->access(); }
    link::Link &link() const { return connection->link(); }
    link::FaultLink *faultLink() const { return connection->faultLink(); }
    model::SimEndpoint *simEndpoint() const { return connection->simEndpoint(); }

    // The simulated device's side: module `i` of the node, its address and dictionary.
    dev::sim::HcsModule &simModule(std::size_t i = 0) const
    {
        return simEndpoint()->node()->module(i);
    }
    int address(std::size_t i = 0) const { return simEndpoint()->moduleAddress(i); }
    const dev::Dictionary &dictionary() const
    {
        return *dictionaries().find(simEndpoint()->spec().family);
    }

    // The master's side after identify(): module `i` as identified and one of its rows.
    const model::ModuleInfo &module(std::size_t i = 0) const { return modules.at(i); }
    const dev::ParamMeta &row(const char *name, std::size_t i = 0) const
    {
        const dev::ParamMeta *row = module(i).dictionary->find(name);
        EXPECT_TRUE(row) << name;
        return *row;
    }

    // Opens (again) and waits until the link is open.
    bool open()
    {
        if (!connection->isOpen())
            connection->open();
        return waitUntil([&] { return connection->isOpen(); });
    }

    // Identifies every module address of the connection into `modules`.
    bool identify()
    {
        modules.clear();
        for (int address : connection->moduleAddresses()) {
            std::optional<model::IdentifyResult> identified;
            access().identify(address, [&](const model::IdentifyResult &r) { identified = r; });
            if (!waitFor(identified) || !identified->ok) {
                ADD_FAILURE() << "module " << address << " not identified";
                return false;
            }
            modules.push_back(identified->module);
        }
        return true;
    }

    // Reads one row of an identified module (bounded wait); nullopt on failure.
    std::optional<double> read(const char *name, std::size_t i = 0)
    {
        std::optional<model::ReadResult> result;
        access().read(module(i).address, {&row(name, i)}, model::Priority::User,
                      [&](const model::ReadResult &r) { result = r; });
        if (!waitFor(result) || !result->complete() || result->values.empty())
            return std::nullopt;
        return dev::rawNumber(result->values.front().value);
    }
};

// The connection built and opened; nullptr (with a test failure) when it cannot be.
inline std::unique_ptr<SimRig> openSim(const SimSetup &setup)
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = setup.family;
    spec.sim.modules = setup.modules;
    spec.sim.factory = setup.factory;
    if (!setup.protocol.empty()) {
        spec.sim.protocol = dev::fromKey<dev::LinkProtocol>(setup.protocol);
        if (!spec.sim.protocol) {
            ADD_FAILURE() << "no link protocol '" << setup.protocol << "'";
            return nullptr;
        }
    }
    spec.fault = setup.fault;
    auto made = model::Connection::create(spec, dictionaries());
    if (!made.ok()) {
        ADD_FAILURE() << made.error().toStdString();
        return nullptr;
    }
    auto rig = std::make_unique<SimRig>();
    rig->connection = std::move(made).value();
    if (setup.options)
        rig->session().setOptions(*setup.options);
    if (!rig->open()) {
        ADD_FAILURE() << "the simulator link did not open";
        return nullptr;
    }
    return rig;
}

inline std::unique_ptr<SimRig> openSim(const std::string &family, std::size_t modules = 1)
{
    return openSim(SimSetup{family, modules, {}, {}, {}});
}

// Opened, and every module identified.
inline std::unique_ptr<SimRig> connectSim(const SimSetup &setup)
{
    auto rig = openSim(setup);
    if (!rig || !rig->identify())
        return nullptr;
    return rig;
}

inline std::unique_ptr<SimRig> connectSim(const std::string &family, std::size_t modules = 1)
{
    return connectSim(SimSetup{family, modules, {}, {}, {}});
}

// The module's stored word for `row`, as the row's type reads it.
inline double storedRaw(dev::sim::HcsModule &module, const dev::ParamMeta &row)
{
    const auto outcome = module.read(static_cast<std::uint16_t>(*row.id), 1);
    EXPECT_EQ(outcome.exception, 0) << row.name;
    if (outcome.values.empty())
        return -1e9;
    return dev::access::registerToRaw(row, outcome.values.front());
}

} // namespace vt::test
