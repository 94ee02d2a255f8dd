// A connection to the built-in simulator for the session tests: SimLink (optionally behind a
// FaultLink) → Session → DeviceAccess, with bounded waits on the event loop (never sleeps).
#pragma once

#include "access/hcs_rows.h"
#include "access/modbus_adapter.h"
#include "dict/dictionary_loader.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/session/sim_endpoint.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"
#include "transports/fault_link.h"
#include "transports/fault_spec.h"
#include "transports/sim_link.h"

#include <QTest>
#include <gtest/gtest.h>
#include <memory>
#include <optional>

namespace vt::test {

inline constexpr int kWaitMs = 20'000;

inline const dev::DictionarySet &dictionaries()
{
    return *dev::builtinDictionaries();
}

struct SimConnection
{
    std::unique_ptr<link::Link> link; // the SimLink, or the FaultLink around it
    link::SimLink *sim = nullptr;
    link::FaultLink *fault = nullptr;
    model::SimEndpoint *endpoint = nullptr;
    std::unique_ptr<model::Session> session;
    std::unique_ptr<model::DeviceAccess> access;

    dev::sim::HcsModule &module(std::size_t i = 0) { return endpoint->node()->module(i); }
    int address(std::size_t i = 0) const { return endpoint->moduleAddress(i); }
    const dev::Dictionary &dictionary() const
    {
        return *dictionaries().find(endpoint->spec().family);
    }

    bool open()
    {
        link->open();
        return QTest::qWaitFor([&] { return link->state() == link::LinkState::Open; }, kWaitMs);
    }
};

inline std::unique_ptr<SimConnection>
connectSim(const std::string &family, std::size_t modules = 1,
           std::optional<link::FaultSpec> faults = std::nullopt, model::SessionOptions options = {})
{
    auto c = std::make_unique<SimConnection>();
    model::SimSpec spec;
    spec.family = family;
    spec.modules = modules;
    auto made = model::makeSimLink(spec, &dictionaries());
    if (!made.ok()) {
        ADD_FAILURE() << made.error().toStdString();
        return nullptr;
    }
    c->sim = made->get();
    c->endpoint = model::simEndpointOf(*c->sim);
    if (faults) {
        auto fault = std::make_unique<link::FaultLink>(std::move(made).value(), *faults);
        c->fault = fault.get();
        c->link = std::move(fault);
    } else {
        c->link = std::move(made).value();
    }
    std::unique_ptr<dev::access::ProtocolAdapter> adapter;
    if (c->endpoint->spec().protocol == dev::LinkProtocol::ModbusTcp)
        adapter = std::make_unique<dev::access::ModbusTcpAdapter>(dev::access::hcsFamilyOf(family));
    else
        adapter = std::make_unique<dev::access::ModbusRtuAdapter>(dev::access::hcsFamilyOf(family));
    c->session = std::make_unique<model::Session>(c->link.get(), std::move(adapter), options);
    c->access = std::make_unique<model::DeviceAccess>(*c->session, dictionaries());
    if (!c->open()) {
        ADD_FAILURE() << "the simulator link did not open";
        return nullptr;
    }
    return c;
}

// Runs the event loop until `flag` is set (bounded).
template<typename T> bool waitFor(const std::optional<T> &value, int timeoutMs = kWaitMs)
{
    return QTest::qWaitFor([&] { return value.has_value(); }, timeoutMs);
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
