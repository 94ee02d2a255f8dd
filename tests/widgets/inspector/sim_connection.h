// The simulator rig (sim_rig.h) with a TelegramLog that records every frame, for the inspector's
// send and list tests. The modules are named from the connection, not identified, so the log
// holds only what a test sends.
#pragma once

#include "model/telegrams/telegram_log.h"
#include "model/telegrams/telegram_recorder.h"
#include "sim_rig.h"

namespace vt::test {

struct LoggedSim
{
    std::unique_ptr<model::TelegramLog> log = std::make_unique<model::TelegramLog>();
    std::unique_ptr<model::Connection> connection;
    std::unique_ptr<model::TelegramRecorder> recorder;
    std::vector<model::ModuleInfo> modules;

    // `family` and `protocol` as in SimSetup; opened, recorder attached.
    bool open(const std::string &family, std::size_t count = 1, const std::string &protocol = {})
    {
        auto rig = openSim(SimSetup{family, count, protocol, {}, {}});
        if (!rig)
            return false;
        connection = std::move(rig->connection);
        recorder = std::make_unique<model::TelegramRecorder>(connection->session(), *log);
        for (int address : connection->moduleAddresses()) {
            model::ModuleInfo m;
            m.address = address;
            m.dictionary = dictionaries().find(family);
            modules.push_back(m);
        }
        return true;
    }

    ~LoggedSim()
    {
        recorder.reset();
        connection.reset();
    }
};

} // namespace vt::test
