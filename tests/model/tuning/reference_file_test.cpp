// The reference file (model/tuning/reference_file.h): what it writes reads back the same, and the
// reader refuses what it does not understand with a reason — another format, a newer version, too
// deep a nesting, too many tests, a damaged run inside.
#include "model/tuning/reference_file.h"

#include <cmath>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

RunFileData aRun(double from, double to)
{
    RunFileData run;
    run.number = 1;
    run.started = "2026-11-27T08:00:00.000";
    run.module = 3;
    run.family = "dma-pn-v51";
    run.mode = "3";
    run.setValue = "A1.01";
    run.response = "d1.11";
    run.spec.kind = SignalKind::Step;
    run.spec.from = from;
    run.spec.to = to;
    run.spec.hold = 0.5;
    run.end = "finished";
    run.restored = true;
    run.writes = 2;
    run.cycles = 3;
    run.setValueSamples = {{0, 0.5}, {from, to}};
    run.channelNames = {"d1.10", "d1.11"};
    run.channels = {{{0, 0.4, 0.9}, {from, from, to}}, {{0, 0.4, 0.9}, {from, from + 0.1, to}}};
    run.settings = {{"C1.13", 200}};
    return run;
}

ReferenceFileData aReference()
{
    ReferenceFileData r;
    r.saved = "2026-11-27T09:00:00.000";
    r.family = "dma-pn-v51";
    r.version = "51.02";
    r.mode = "3";
    r.address = 3;
    r.setValue = "A1.01";
    r.centre = 4;
    r.amplitude = 1;
    r.settings = {{"C1.13", 200, "2.00", ""}, {"C1.17", 0, "0.0", "V/s"}};
    r.tests = {{"step-up", aRun(4, 5)}, {"step-down", aRun(3, 4)}};
    r.figures = {{"step-up", "rise-time", 0.05, "s"}, {"step-up", "settling-time", NAN, "s"}};
    return r;
}

TEST(ReferenceFile, WhatItWritesReadsBackTheSame)
{
    const ReferenceFileData r = aReference();
    const auto back = parseReferenceFile(referenceJson(r));
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->family, "dma-pn-v51");
    EXPECT_EQ(back->version, "51.02");
    EXPECT_EQ(back->mode, "3");
    EXPECT_EQ(back->address, 3);
    EXPECT_EQ(back->setValue, "A1.01");
    EXPECT_DOUBLE_EQ(back->centre, 4);
    EXPECT_DOUBLE_EQ(back->amplitude, 1);
    ASSERT_EQ(back->settings.size(), 2u);
    EXPECT_EQ(back->settings[1].name, "C1.17");
    EXPECT_EQ(back->settings[1].display, "0.0");
    EXPECT_EQ(back->settings[1].unit, "V/s");
    ASSERT_EQ(back->tests.size(), 2u);
    EXPECT_EQ(back->tests[1].key, "step-down");
    EXPECT_DOUBLE_EQ(back->tests[1].run.spec.from, 3);
    ASSERT_EQ(back->tests[0].run.channels.size(), 2u);
    EXPECT_EQ(back->tests[0].run.channels[1].y, r.tests[0].run.channels[1].y);
    EXPECT_EQ(back->tests[0].run.settings.size(), 1u);
    ASSERT_EQ(back->figures.size(), 2u);
    EXPECT_DOUBLE_EQ(back->figures[0].value, 0.05);
    EXPECT_TRUE(std::isnan(back->figures[1].value)); // written as null
}

void refuses(const std::string &text, const std::string &why)
{
    const auto parsed = parseReferenceFile(text);
    ASSERT_FALSE(parsed.ok()) << text.substr(0, 200);
    EXPECT_NE(parsed.error().find(why), std::string::npos) << why << ": " << parsed.error();
}

std::string replaced(std::string text, const std::string &what, const std::string &with)
{
    const auto at = text.find(what);
    EXPECT_NE(at, std::string::npos) << what;
    return at == std::string::npos ? text : text.replace(at, what.size(), with);
}

TEST(ReferenceFile, RefusesWhatItDoesNotUnderstandWithAReason)
{
    const std::string good = referenceJson(aReference());
    refuses("", "not a valid JSON");
    refuses(good.substr(0, good.size() / 2), "not a valid JSON");
    refuses(R"({"format": "valvetune-run"})", "not a ValveTune reference");
    refuses(replaced(good, "\"format_version\": 1", "\"format_version\": 2"), "newer ValveTune");
    refuses(replaced(good, "\"address\": 3", "\"address\": 300"), "address");
    refuses(replaced(good, "\"centre\": 4.0", "\"centre\": \"4\""), "centre");
    refuses(std::string(40, '[') + std::string(40, ']'), "nested too deeply");
    refuses(replaced(good, "\"mode\": \"3\"", "\"mode\": 3"), "mode");
    // The run inside is checked as a run file: a time going back in its recording.
    refuses(replaced(good, "0.900000,", "0.100000,"), "test step-up: CSV line");
}

TEST(ReferenceFile, RefusesMoreTestsThanItHolds)
{
    ReferenceFileData r = aReference();
    while (r.tests.size() <= kMaxReferenceTests)
        r.tests.push_back({"step-up", aRun(4, 5)});
    refuses(referenceJson(r), "\"tests\" is not a list of at most 8");
}

TEST(ReferenceFile, RefusesATextLongerThanANameShouldBe)
{
    ReferenceFileData r = aReference();
    r.settings[0].unit = std::string(300, 'u');
    refuses(referenceJson(r), "settings: \"unit\" is not a short text");
}

} // namespace
} // namespace vt::model
