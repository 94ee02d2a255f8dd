// TcpLink against a QTcpServer on 127.0.0.1 (TCP link, connect
// timeout, failure on refusal and on the peer closing).
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/tcp_link.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

namespace {

using namespace std::chrono_literals;
using vt::link::LinkState;
using vt::link::TcpLink;
using vt::test::waitForCount;
using vt::test::waitForState;

struct Server
{
    Server() { ok = server.listen(QHostAddress::LocalHost, 0); }
    // Waits for the link's connection on the server side.
    QTcpSocket *accept()
    {
        if (!server.hasPendingConnections() &&
            !vt::test::waitUntil([&] { return server.hasPendingConnections(); }, vt::test::kWaitMs))
            return nullptr;
        return server.nextPendingConnection();
    }
    QTcpServer server;
    bool ok = false;
};

TEST(TcpLink, RoundTripWithAServer)
{
    Server srv;
    ASSERT_TRUE(srv.ok);
    TcpLink link(QStringLiteral("127.0.0.1"), srv.server.serverPort());
    EXPECT_EQ(link.description(), QStringLiteral("tcp 127.0.0.1:%1").arg(srv.server.serverPort()));
    QSignalSpy received(&link, &TcpLink::received);
    link.open();
    EXPECT_EQ(link.state(), LinkState::Opening);
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    QTcpSocket *peer = srv.accept();
    ASSERT_NE(peer, nullptr);

    const QByteArray mbap = QByteArray::fromHex("000100000006010300000008");
    link.send(mbap);
    QByteArray atServer;
    ASSERT_TRUE(vt::test::waitUntil(
        [&] {
            atServer += peer->readAll();
            return atServer.size() >= mbap.size();
        },
        vt::test::kWaitMs));
    EXPECT_EQ(atServer, mbap);

    const QByteArray answer = QByteArray::fromHex("00010000000501030200ff");
    peer->write(answer);
    QByteArray got;
    ASSERT_TRUE(vt::test::collectBytes(received, got, answer.size()));
    EXPECT_EQ(got, answer);
}

TEST(TcpLink, RefusedConnectionFails)
{
    quint16 port = 0;
    {
        Server srv; // find a free port, then free it again
        ASSERT_TRUE(srv.ok);
        port = srv.server.serverPort();
    }
    TcpLink link(QStringLiteral("127.0.0.1"), port);
    QSignalSpy failed(&link, &TcpLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(QString::number(port)))
        << failed.first().value(0).toString().toStdString();
}

TEST(TcpLink, ServerClosingFailsTheLinkAndReopenWorks)
{
    Server srv;
    ASSERT_TRUE(srv.ok);
    TcpLink link(QStringLiteral("127.0.0.1"), srv.server.serverPort());
    QSignalSpy failed(&link, &TcpLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    QTcpSocket *peer = srv.accept();
    ASSERT_NE(peer, nullptr);

    peer->close();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(QStringLiteral("closed")))
        << failed.first().value(0).toString().toStdString();

    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    EXPECT_NE(srv.accept(), nullptr);
    EXPECT_EQ(failed.count(), 1);
}

// A listener whose accept queue is full: Linux drops further SYNs, so a connect to it hangs
// until the client gives up — the one deterministic way to make a local connect time out.
class SilentListener
{
public:
    SilentListener()
    {
        m_listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        ::inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
        socklen_t length = sizeof address;
        auto *raw = reinterpret_cast<sockaddr *>(&address);
        if (m_listener < 0 || ::bind(m_listener, raw, length) != 0 ||
            ::listen(m_listener, 0) != 0 || ::getsockname(m_listener, raw, &length) != 0)
            return;
        port = ntohs(address.sin_port);
        for (int i = 0; i < 4; ++i) { // never accepted: they fill the queue
            const int c = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
            ::connect(c, raw, length);
            m_fillers.push_back(c);
        }
    }
    ~SilentListener()
    {
        for (int c : m_fillers)
            ::close(c);
        if (m_listener >= 0)
            ::close(m_listener);
    }
    quint16 port = 0;

private:
    int m_listener = -1;
    std::vector<int> m_fillers;
};

TEST(TcpLink, ConnectTimeoutFiresWhenNobodyAnswers)
{
    SilentListener silent;
    ASSERT_NE(silent.port, 0);
    TcpLink link(QStringLiteral("127.0.0.1"), silent.port);
    link.setConnectTimeout(100ms);
    QSignalSpy failed(&link, &TcpLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(QStringLiteral("timed out")))
        << failed.first().value(0).toString().toStdString();
}

TEST(TcpLink, CloseIsImmediateAndSilent)
{
    Server srv;
    ASSERT_TRUE(srv.ok);
    TcpLink link(QStringLiteral("127.0.0.1"), srv.server.serverPort());
    QSignalSpy failed(&link, &TcpLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    link.close();
    EXPECT_EQ(link.state(), LinkState::Closed);
    link.send(QByteArrayLiteral("dropped")); // logged, not sent, no crash
    EXPECT_FALSE(failed.wait(100));
}

TEST(TcpLink, ParsesEndpoints)
{
    const auto a = TcpLink::parseEndpoint(u"192.168.0.10:1502");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->host, QStringLiteral("192.168.0.10"));
    EXPECT_EQ(a->port, 1502);
    const auto b = TcpLink::parseEndpoint(u"plc.local");
    ASSERT_TRUE(b);
    EXPECT_EQ(b->port, 502);
    const auto c = TcpLink::parseEndpoint(u"[::1]:8502");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->host, QStringLiteral("::1"));
    EXPECT_EQ(c->port, 8502);
    EXPECT_EQ(TcpLink(c->host, c->port).description(), QStringLiteral("tcp [::1]:8502"));
    for (const char16_t *bad : {u"", u":502", u"host:0", u"host:70000", u"host:x", u"[::1"})
        EXPECT_FALSE(TcpLink::parseEndpoint(bad)) << QString::fromUtf16(bad).toStdString();
}

} // namespace
