// A Connection to the built-in simulator with a TelegramLog and its recorder, for the
// inspector's send and list tests. Waits on signals with a bound, never sleeps.
#pragma once

#include "dict/dictionary_loader.h"
#include "model/session/connection.h"
#include "model/session/telegram_recorder.h"
#include "model/telegram_log.h"

#include <QSignalSpy>
#include <gtest/gtest.h>
#include <memory>

namespace vt::test {

inline constexpr int kWaitMs = 20'000;

struct SimRig
{
    std::unique_ptr<model::TelegramLog> log = std::make_unique<model::TelegramLog>();
    std::unique_ptr<model::Connection> connection;
    std::unique_ptr<model::TelegramRecorder> recorder;
    std::vector<model::ModuleInfo> modules;

    // `family` and `protocol` as in SimSpec ("dma-pn-v51", "opat", "wandfluh-sd7"; "" = the
    // default link); opened, recorder attached.
    bool open(const std::string &family, std::size_t count = 1, const std::string &protocol = {})
    {
        model::ConnectionSpec spec;
        spec.kind = model::ConnectionKind::Sim;
        spec.sim.family = family;
        spec.sim.modules = count;
        spec.sim.protocol = dev::fromKey<dev::LinkProtocol>(protocol);
        auto made = model::Connection::create(spec, *dev::builtinDictionaries());
        if (!made.ok())
            return false;
        connection = std::move(made).value();
        recorder = std::make_unique<model::TelegramRecorder>(connection->session(), *log);
        QSignalSpy opened(connection.get(), &model::Connection::opened);
        connection->open();
        if (!connection->isOpen() && !opened.wait(kWaitMs))
            return false;
        for (int address : connection->moduleAddresses()) {
            model::ModuleInfo m;
            m.address = address;
            m.dictionary = dev::builtinDictionaries()->find(family);
            modules.push_back(m);
        }
        return true;
    }

    ~SimRig()
    {
        recorder.reset();
        connection.reset();
    }
};

} // namespace vt::test
