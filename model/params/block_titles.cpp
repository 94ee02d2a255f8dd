#include "block_titles.h"

#include <QCoreApplication>
#include <algorithm>
#include <array>

namespace vt::model {

std::vector<std::string> blockOrder(const dev::Dictionary &dictionary)
{
    static const std::array<const char *, 9> hcs = {"d", "C", "E", "A",     "L",
                                                    "r", "S", "B", "system"};
    std::vector<std::string> seen;
    for (const dev::ParamMeta &row : dictionary.params)
        if (std::find(seen.begin(), seen.end(), row.block) == seen.end())
            seen.push_back(row.block);
    std::vector<std::string> order;
    for (const char *key : hcs)
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            order.emplace_back(key);
    for (const std::string &key : seen)
        if (std::find(order.begin(), order.end(), key) == order.end())
            order.push_back(key);
    return order;
}

QString blockTitle(const std::string &block)
{
    struct Title
    {
        const char *key;
        const char *text;
    };
    // HCS manuals ("Parameter list"); Wandfluh ED1/SD1 §4.8 and SD7 §4.4 function blocks.
    static const Title titles[] = {
        {"d", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Display values")},
        {"C", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Controller")},
        {"E", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Settings")},
        {"A", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Bus values")},
        {"L", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Linearisation")},
        {"r", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Ramps")},
        {"S", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Reserved (S)")},
        {"B", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "PROFIdrive set values")},
        {"system", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "System")},
        {"db", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Device")},
        {"dav", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Drive actual value conditioning")},
        {"dop", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Drive output processing")},
        {"dpc", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Drive position control")},
        {"dcol", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Open loop movement")},
        {"dsc", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Velocity control axis")},
        {"vpoc", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Spool position control open loop")},
        {"vprc", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Pressure control")},
        {"av", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Actual value")},
        {"ch", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Channel")},
        {"ramp", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Ramp")},
        {"npc", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "n-point controller")},
        {"cv", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Command value")},
        {"fcv", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Fixed command values")},
        {"ctrl", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Controller")},
        {"ao", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Analogue output")},
        {"sol1", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Solenoid 1")},
        {"sol2", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "Solenoid 2")},
        {"hart", QT_TRANSLATE_NOOP("vt::model::BlockTitles", "HART")},
    };
    for (const Title &t : titles)
        if (block == t.key)
            return QCoreApplication::translate("vt::model::BlockTitles", t.text);
    return QString::fromStdString(block);
}

} // namespace vt::model
