#include "app/gui/app_settings.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using vt::app::AppSettings;

TEST(AppSettings, RoundTripsThroughTheIniFile)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString ini = dir.filePath("valvetune.ini");
    {
        AppSettings s(ini);
        EXPECT_TRUE(s.language().isEmpty()); // first start: nothing chosen yet
        s.setLanguage("de");
        s.setWindowGeometry(QByteArray("\x01\x02geometry", 10));
        s.setWindowState(QByteArray("state"));
        s.setRecentFiles({"/plant/press1.vtpar", "/plant/press2.vtpar"});
        s.sync();
    }
    AppSettings again(ini);
    EXPECT_EQ(again.language(), "de");
    EXPECT_EQ(again.windowGeometry(), QByteArray("\x01\x02geometry", 10));
    EXPECT_EQ(again.windowState(), QByteArray("state"));
    EXPECT_EQ(again.recentFiles(), (QStringList{"/plant/press1.vtpar", "/plant/press2.vtpar"}));
}
