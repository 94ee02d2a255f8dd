// The device image and the actuator ledger on their own: what counts as current (this
// connection, younger than the limit), which changes are signalled, and what is offered back.
#include "model/session/actuator_ledger.h"
#include "model/session/device_image.h"
#include "sim_rig.h"

#include <QSignalSpy>

namespace vt::test {
namespace {

const dev::Dictionary &dma()
{
    return *dictionaries().find("dma-pn-v51");
}
const dev::ParamMeta *row(const char *name)
{
    return dma().find(name);
}

TEST(DeviceImage, AValueIsCurrentOnlyOnItsConnectionAndWhileYoung)
{
    model::DeviceImage image;
    image.beginConnection();
    QSignalSpy changed(&image, &model::DeviceImage::changed);
    image.recordRead(1, {{row("C1.07"), 500.0}});
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(image.currentValue(1, row("C1.07")), dev::RawValue{500.0});
    EXPECT_FALSE(image.value(2, row("C1.07"))); // another module

    image.recordRead(1, {{row("C1.07"), 500.0}}); // the same answer again: no signal
    EXPECT_EQ(changed.count(), 1);

    image.endConnection();
    EXPECT_FALSE(image.currentValue(1, row("C1.07")));
    EXPECT_EQ(image.value(1, row("C1.07")), dev::RawValue{500.0}); // still known, not current
    image.beginConnection();
    EXPECT_FALSE(image.currentValue(1, row("C1.07"))); // from before the reconnect
    image.recordRead(1, {{row("C1.07"), 500.0}});      // same value, now current again: signalled
    EXPECT_EQ(changed.count(), 2);
    EXPECT_TRUE(image.currentValue(1, row("C1.07")));

    image.setMaxAge(std::chrono::seconds(0));
    const model::ImageEntry *entry = image.entry(1, row("C1.07"));
    ASSERT_NE(entry, nullptr);
    EXPECT_FALSE(image.isCurrent(*entry, entry->when + std::chrono::seconds(1)));
}

TEST(ActuatorLedger, KeepsTheFirstOriginalAndForgetsARowPutBackByHand)
{
    model::DeviceImage image;
    image.beginConnection();
    model::ActuatorLedger ledger(image);
    const dev::ParamMeta *a101 = row("A1.01");
    const dev::ParamMeta *c107 = row("C1.07");
    ASSERT_TRUE(a101->movesActuator);
    ASSERT_FALSE(c107->movesActuator);
    image.recordRead(1, {{a101, 0.0}, {c107, 500.0}});
    image.recordWritten(1, c107, 600.0); // a plain setting: not in the ledger
    EXPECT_TRUE(ledger.empty());

    image.recordWritten(1, a101, 2000.0);
    image.recordWritten(1, a101, 1000.0);
    ASSERT_EQ(ledger.changes().size(), 1u);
    EXPECT_EQ(ledger.changes()[0].original, dev::RawValue{0.0});
    EXPECT_EQ(ledger.changes()[0].now, dev::RawValue{1000.0});
    const auto plan = ledger.restorePlan();
    ASSERT_EQ(plan.at(1).size(), 1u);
    EXPECT_EQ(plan.at(1)[0].value, dev::RawValue{0.0});

    image.recordWritten(1, a101, 0.0); // back where it was
    EXPECT_TRUE(ledger.empty());

    image.recordWritten(2, a101, 500.0); // never read: cannot be put back
    ASSERT_EQ(ledger.unrestorable().size(), 1u);
    EXPECT_TRUE(ledger.restorePlan().empty());
}

} // namespace
} // namespace vt::test
