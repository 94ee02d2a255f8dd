#include "model/assert_handler.h"

#include <QApplication>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <cstdlib>
#include <gtest/gtest.h>

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Never touch the user's real settings or data from a test; the session logs go to a
    // temporary folder (test_sessions.cpp does the same for the binaries without this main).
    QStandardPaths::setTestModeEnabled(true);
    QTemporaryDir sessions;
    if (qEnvironmentVariableIsEmpty("VT_AUDIT_DIR") && sessions.isValid())
        qputenv("VT_AUDIT_DIR", QFile::encodeName(sessions.path()));
    QApplication app(argc, argv);
    vt::model::installQtAssertHandler(); // as valvetune's main() does
    QCoreApplication::setOrganizationName(QStringLiteral("ValveTuneTests"));
    QCoreApplication::setApplicationName(QStringLiteral("ValveTuneTests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
