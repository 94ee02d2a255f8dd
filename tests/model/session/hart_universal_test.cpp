// The SD7's universal-command data through the session (HART-7 manual §5.1): its texts read and
// written (commands 12/13/20 and 17/18/22), the dynamic variables of command 3 in one exchange,
// and command 48's warning "status bytes mismatch" delivered as a value with a warning.
#include "model/session/write_job.h"
#include "sim/hart_device.h"
#include "sim_rig.h"

namespace vt::test {
namespace {

std::optional<model::ReadResult> readRows(SimRig &rig, std::vector<const char *> names)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const char *name : names)
        rows.push_back(&rig.row(name));
    std::optional<model::ReadResult> result;
    rig.access().read(rig.module().address, rows, model::Priority::User,
                      [&](const model::ReadResult &r) { result = r; });
    if (!waitFor(result))
        return std::nullopt;
    return result;
}

std::string text(const model::ReadResult &result, std::size_t i)
{
    const auto *s = std::get_if<std::string>(&result.values.at(i).value);
    return s ? *s : "(not a text)";
}

std::vector<model::WriteItem> write(SimRig &rig, const char *name, dev::RawValue value)
{
    model::WriteItem item;
    item.row = &rig.row(name);
    item.value = std::move(value);
    model::WriteJob job(rig.access(), rig.module().address, *rig.module().dictionary, {item},
                        model::AuditOrigin::Editor);
    QSignalSpy finished(&job, &model::WriteJob::finished);
    job.start();
    EXPECT_TRUE(finished.wait(kWaitMs));
    return job.items();
}

TEST(HartUniversal, ReadsTheDeliveryTextsAndDate)
{
    auto rig = connectSim("wandfluh-sd7");
    ASSERT_TRUE(rig);
    const auto r = readRows(*rig, {"hart_Tag", "hart_LongTag", "hart_Descriptor", "hart_Message",
                                   "hart_DateDay", "hart_DateMonth", "hart_DateYear"});
    ASSERT_TRUE(r);
    ASSERT_TRUE(r->complete());
    ASSERT_EQ(r->values.size(), 7u);
    // HART-7 manual §6.4: the delivery state.
    EXPECT_EQ(text(*r, 0), "WAGSD733");
    EXPECT_EQ(text(*r, 1), "Wandfluh AG - SD733");
    EXPECT_EQ(text(*r, 2), "WAG ELECTRONIC");
    EXPECT_EQ(text(*r, 3), rig->simEndpoint()->hart()->message());
    EXPECT_EQ(dev::rawNumber(r->values[4].value), 15);
    EXPECT_EQ(dev::rawNumber(r->values[5].value), 3);
    EXPECT_EQ(dev::rawNumber(r->values[6].value), 124); // 2024 − 1900
}

// Command 18 carries tag, descriptor and date together: writing the tag keeps the other two.
TEST(HartUniversal, WritesEachTextWithReadBackAndKeepsItsNeighbours)
{
    auto rig = connectSim("wandfluh-sd7");
    ASSERT_TRUE(rig);
    ASSERT_TRUE(readRows(*rig, {"hart_Tag", "hart_Descriptor", "hart_DateDay"}));
    auto items = write(*rig, "hart_Tag", std::string("PUMP 7"));
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified)
        << items.front().reason.text().toStdString();
    items = write(*rig, "hart_LongTag", std::string("Presse 3 Ventil links Ölseite"));
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified);
    items = write(*rig, "hart_Message", std::string("CHECKED 2026-11-27"));
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified);
    items = write(*rig, "hart_DateDay", 27.0);
    EXPECT_EQ(items.front().status, model::WriteStatus::Verified);

    const dev::sim::HartDevice &sd7 = *rig->simEndpoint()->hart();
    EXPECT_EQ(sd7.tag(), "PUMP 7");
    EXPECT_EQ(sd7.longTag(), "Presse 3 Ventil links Ölseite");
    EXPECT_EQ(sd7.message(), "CHECKED 2026-11-27");
    EXPECT_EQ(sd7.descriptor(), "WAG ELECTRONIC"); // kept by the tag's and the date's write
    EXPECT_EQ(sd7.date().day, 27);
    EXPECT_EQ(sd7.date().month, 3);
}

// §5.1.4: PV, SV, TV, QV and the loop current come in one command 3.
TEST(HartUniversal, DynamicVariablesShareOneExchange)
{
    auto rig = connectSim("wandfluh-sd7");
    ASSERT_TRUE(rig);
    rig->simEndpoint()->hart()->setLoopCurrent(12.0f);
    QSignalSpy sent(&rig->session(), &model::Session::frameSent);
    const auto r = readRows(
        *rig, {"hart_TvValue", "hart_PvValue", "hart_SvValue", "hart_QvValue", "hart_LoopCurrent"});
    ASSERT_TRUE(r);
    ASSERT_TRUE(r->complete());
    EXPECT_EQ(sent.count(), 1);
    EXPECT_FLOAT_EQ(float(dev::rawNumber(r->values[4].value)), 12.0f);
}

// HART 7 command 48: the master sends the status bytes it last read; when they changed the
// device answers with the new bytes and the warning 14. The value counts, the warning is said.
TEST(HartUniversal, AStatusChangeArrivesAsAValueWithAWarning)
{
    auto rig = connectSim("wandfluh-sd7");
    ASSERT_TRUE(rig);
    auto first = readRows(*rig, {"hart_DeviceSpecificStatus"});
    ASSERT_TRUE(first && first->complete());
    EXPECT_EQ(first->values.front().warningCode, 0);
    EXPECT_EQ(dev::rawNumber(first->values.front().value), 0);

    rig->simEndpoint()->hart()->injectError(0x5231);
    auto second = readRows(*rig, {"hart_DeviceSpecificStatus"});
    ASSERT_TRUE(second->complete()); // a warning is not a failure
    ASSERT_TRUE(second->complete()); // a warning is not a failure
    EXPECT_EQ(second->values.front().warningCode, 14);
    EXPECT_FALSE(second->values.front().warning.en.empty());
    // Bytes 0..1 hold the error code in the simulator's layout (docs/SIMULATOR-WANDFLUH.md).
    EXPECT_EQ(std::uint32_t(dev::rawNumber(second->values.front().value)) >> 16, 0x5231u);

    auto third = readRows(*rig, {"hart_DeviceSpecificStatus"});
    ASSERT_TRUE(third && third->complete());
    EXPECT_EQ(third->values.front().warningCode, 0); // nothing changed since
}

} // namespace
} // namespace vt::test
