// LinkStatusWidget: against a simulator connection the texts follow the link state, the identified
// module and the session counters as requests complete.
#include "connect_test_support.h"
#include "model/session/connection.h"
#include "transports/fault_spec.h"
#include "transports/link.h"
#include "widgets/connect/link_status_widget.h"

#include <QLabel>
#include <QSignalSpy>
#include <QTest>

namespace vt::test {
namespace {

std::unique_ptr<model::Connection> simConnection(const std::string &family)
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = family;
    auto made = model::Connection::create(spec, dictionaries());
    EXPECT_TRUE(made.ok());
    return made.ok() ? std::move(made).value() : nullptr;
}

TEST(LinkStatusWidget, FollowsStateIdentityAndCounters)
{
    ui::LinkStatusWidget widget;
    const QString idle = widget.linkText();
    EXPECT_EQ(idle, link::linkStateText(link::LinkState::Closed));

    auto connection = simConnection("dma-pn-v51");
    ASSERT_TRUE(connection);
    widget.setConnection(connection.get(), {});
    EXPECT_TRUE(widget.linkText().contains(QStringLiteral("dma-pn-v51")));
    EXPECT_TRUE(widget.countersText().contains(QStringLiteral("requests 0")));

    QSignalSpy opened(connection.get(), &model::Connection::opened);
    connection->open();
    ASSERT_TRUE(opened.count() > 0 || opened.wait(kWaitMs));
    const QString connected = link::linkStateText(link::LinkState::Open);
    EXPECT_TRUE(waitUntil([&] { return widget.linkText().contains(connected); }, kWaitMs))
        << widget.linkText().toStdString();

    // Identify the module (real requests on the simulator) and show who answered.
    std::optional<model::IdentifyResult> identified;
    const int address = connection->moduleAddresses().front();
    connection->access().identify(address, [&](const model::IdentifyResult &r) { identified = r; });
    ASSERT_TRUE(waitUntil([&] { return identified.has_value(); }, kWaitMs));
    ASSERT_TRUE(identified->ok) << identified->message.toStdString();
    widget.setModules({identified->module});
    EXPECT_TRUE(widget.identityText().contains(QStringLiteral("V51")))
        << widget.identityText().toStdString();
    EXPECT_TRUE(widget.identityText().startsWith(QStringLiteral("#1 ")))
        << widget.identityText().toStdString();
    // A node of five: the status bar keeps room for messages, the whole text is on hover.
    widget.setModules(std::vector<model::ModuleInfo>(5, identified->module));
    auto *identity = widget.findChild<QLabel *>(QStringLiteral("identity"));
    ASSERT_TRUE(identity);
    EXPECT_LE(identity->sizeHint().width(), 360);
    EXPECT_EQ(widget.identityText().count(QStringLiteral("#1 ")), 5);
    EXPECT_TRUE(identity->toolTip().contains(widget.identityText()));

    const quint64 requests = connection->session().counters().requests;
    ASSERT_GT(requests, 0u);
    const QString expected = QStringLiteral("requests %1 ").arg(requests);
    EXPECT_TRUE(waitUntil([&] { return widget.countersText().startsWith(expected); }, kWaitMs))
        << widget.countersText().toStdString();

    // Module 9 does not exist on the point-to-point line: the simulator stays silent and the
    // attempts time out.
    bool done = false;
    model::SessionOptions quick = connection->session().options();
    quick.retries = 1;
    quick.turnaround = std::chrono::milliseconds(20);
    connection->session().setOptions(quick);
    connection->access().identify(9, [&](const model::IdentifyResult &) { done = true; });
    ASSERT_TRUE(waitUntil([&] { return done; }, kWaitMs));
    const model::SessionCounters after = connection->session().counters();
    EXPECT_GT(after.timeouts, 0u);
    const QString timeouts = QStringLiteral("timeouts %1 ").arg(after.timeouts);
    EXPECT_TRUE(waitUntil([&] { return widget.countersText().contains(timeouts); }, kWaitMs))
        << widget.countersText().toStdString();

    widget.clearConnection();
    EXPECT_EQ(widget.linkText(), idle);
    EXPECT_TRUE(widget.countersText().isEmpty());
}

TEST(LinkStatusWidget, ShowsWhyTheLinkWasLost)
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    link::FaultSpec cut;
    cut.cutAfterFrames = 2; // the cable is pulled after one exchange
    spec.fault = cut;
    auto made = model::Connection::create(spec, dictionaries());
    ASSERT_TRUE(made.ok());
    std::unique_ptr<model::Connection> connection = std::move(made).value();
    ui::LinkStatusWidget widget;
    widget.setConnection(connection.get(), {});
    QSignalSpy opened(connection.get(), &model::Connection::opened);
    QSignalSpy lost(connection.get(), &model::Connection::lost);
    connection->open();
    ASSERT_TRUE(opened.count() > 0 || opened.wait(kWaitMs));
    connection->access().identify(connection->moduleAddresses().front(),
                                  [](const model::IdentifyResult &) {});
    ASSERT_TRUE(lost.count() > 0 || lost.wait(kWaitMs));
    const QString reason = lost.front().front().toString();
    ASSERT_FALSE(reason.isEmpty());
    EXPECT_TRUE(waitUntil([&] { return widget.linkText().contains(reason); }, kWaitMs))
        << widget.linkText().toStdString();
}

TEST(LinkStatusWidget, ForgetsADestroyedConnection)
{
    ui::LinkStatusWidget widget;
    auto connection = simConnection("opat");
    ASSERT_TRUE(connection);
    widget.setConnection(connection.get(), {});
    QSignalSpy opened(connection.get(), &model::Connection::opened);
    connection->open();
    ASSERT_TRUE(opened.count() > 0 || opened.wait(kWaitMs));
    // Destroying it mid-session (its link closes after its session is gone) must not reach the
    // widget's refresh with a dangling session; ASan watches.
    connection.reset();
    EXPECT_EQ(widget.linkText(), link::linkStateText(link::LinkState::Closed));
}

} // namespace
} // namespace vt::test
