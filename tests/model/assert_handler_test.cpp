// The Qt layers' VT_ASSERT handler: a failed assertion becomes a critical message of the Qt
// message log that carries the assertion's file and line.
#include "model/assert_handler.h"

#include <QString>
#include <gtest/gtest.h>
#include <vector>

namespace {

struct Logged
{
    QtMsgType type;
    QString text;
    QString file;
    int line;
};
std::vector<Logged> g_logged;

void capture(QtMsgType type, const QMessageLogContext &context, const QString &text)
{
    g_logged.push_back({type, text, QString::fromUtf8(context.file), context.line});
}

TEST(AssertHandler, AFailedAssertionIsACriticalMessageWithFileAndLine)
{
    g_logged.clear();
    const vt::AssertHandler previous = vt::setAssertHandler(&vt::model::qtAssertHandler);
    const QtMessageHandler before = qInstallMessageHandler(&capture);
    int recovered = 0;
    const int line = __LINE__ + 1;
    VT_ASSERT(recovered == 1, ++recovered);
    qInstallMessageHandler(before);
    vt::setAssertHandler(previous);

    EXPECT_EQ(recovered, 1);
    ASSERT_EQ(g_logged.size(), 1u);
    EXPECT_EQ(g_logged[0].type, QtCriticalMsg);
    EXPECT_TRUE(g_logged[0].file.endsWith(QStringLiteral("assert_handler_test.cpp")))
        << g_logged[0].file.toStdString();
    EXPECT_EQ(g_logged[0].line, line);
    EXPECT_TRUE(g_logged[0].text.contains(QStringLiteral("recovered == 1")))
        << g_logged[0].text.toStdString();
    EXPECT_TRUE(g_logged[0].text.contains(QStringLiteral("assert_handler_test.cpp:%1").arg(line)))
        << g_logged[0].text.toStdString();
}

} // namespace
