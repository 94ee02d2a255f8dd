#include "model/recent_files.h"

#include <QSignalSpy>
#include <gtest/gtest.h>

using vt::model::RecentFiles;

TEST(RecentFiles, MostRecentFirstWithoutDuplicates)
{
    RecentFiles r(3);
    QSignalSpy spy(&r, &RecentFiles::changed);
    r.add("/a/x.vtpar");
    r.add("/a/y.vtpar");
    r.add("/a/./x.vtpar"); // same file, cleaned path
    EXPECT_EQ(r.files(), (QStringList{"/a/x.vtpar", "/a/y.vtpar"}));
    EXPECT_EQ(spy.count(), 3);
}

TEST(RecentFiles, BoundedToItsLimit)
{
    RecentFiles r(2);
    r.add("/1");
    r.add("/2");
    r.add("/3");
    EXPECT_EQ(r.files(), (QStringList{"/3", "/2"}));
    r.setFiles({"/a", "/b", "/c", "/a"});
    EXPECT_EQ(r.files(), (QStringList{"/a", "/b"}));
}

TEST(RecentFiles, RemoveAndClear)
{
    RecentFiles r;
    r.add("/1");
    r.add("/2");
    r.remove("/1");
    EXPECT_EQ(r.files(), QStringList{"/2"});
    QSignalSpy spy(&r, &RecentFiles::changed);
    r.remove("/not-there");
    EXPECT_EQ(spy.count(), 0);
    r.clear();
    EXPECT_TRUE(r.files().isEmpty());
    EXPECT_EQ(spy.count(), 1);
}
