#include "model/assert_handler.h"

#include <QApplication>
#include <QStandardPaths>
#include <cstdlib>
#include <gtest/gtest.h>

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    // Never touch the user's real settings or data from a test.
    QStandardPaths::setTestModeEnabled(true);
    QApplication app(argc, argv);
    vt::model::installQtAssertHandler(); // as valvetune's main() does
    QCoreApplication::setOrganizationName(QStringLiteral("ValveTuneTests"));
    QCoreApplication::setApplicationName(QStringLiteral("ValveTuneTests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
