// VT_ASSERT: a failed condition reaches the handler with its text, file and line, then the action
// runs; a holding condition does neither. The default handler writes to stderr.
#include "core/vt_assert.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

struct Failure
{
    std::string condition;
    std::string file;
    int line = 0;
};
std::vector<Failure> g_failures;

void record(const char *condition, const char *file, int line)
{
    g_failures.push_back({condition, file, line});
}

// Installs `record` for one test and restores the previous handler after it.
class VtAssert : public ::testing::Test
{
protected:
    void SetUp() override
    {
        g_failures.clear();
        m_previous = vt::setAssertHandler(&record);
    }
    void TearDown() override { vt::setAssertHandler(m_previous); }

private:
    vt::AssertHandler m_previous = nullptr;
};

int guardedAt(const std::vector<int> &values, std::size_t index)
{
    VT_ASSERT(index < values.size(), return -1);
    return values[index];
}

TEST_F(VtAssert, AFailedConditionIsLoggedWithFileAndLineThenTheActionRuns)
{
    const int *missing = nullptr;
    bool recovered = false;
    const int line = __LINE__ + 1;
    VT_ASSERT(missing, recovered = true);
    EXPECT_TRUE(recovered);
    ASSERT_EQ(g_failures.size(), 1u);
    EXPECT_EQ(g_failures[0].condition, "missing");
    EXPECT_NE(g_failures[0].file.find("vt_assert_test.cpp"), std::string::npos)
        << g_failures[0].file;
    EXPECT_EQ(g_failures[0].line, line);

    EXPECT_EQ(guardedAt({1, 2}, 5), -1);
    ASSERT_EQ(g_failures.size(), 2u);
    EXPECT_EQ(g_failures[1].condition, "index < values.size()");
}

TEST_F(VtAssert, AHoldingConditionNeitherLogsNorRunsTheAction)
{
    bool ran = false;
    VT_ASSERT(1 + 1 == 2, ran = true);
    EXPECT_FALSE(ran);
    EXPECT_EQ(guardedAt({1, 2}, 1), 2);
    EXPECT_TRUE(g_failures.empty());
}

TEST_F(VtAssert, BreakAndContinueInTheActionBelongToTheCallersLoop)
{
    int visited = 0;
    for (int i = 0; i < 5; ++i) {
        VT_ASSERT(i != 1, continue);
        VT_ASSERT(i != 3, break);
        ++visited;
    }
    EXPECT_EQ(visited, 2); // 0 and 2; 1 skipped, the loop ended at 3
    EXPECT_EQ(g_failures.size(), 2u);
}

TEST(VtAssertDefault, WritesConditionFileAndLineToStderr)
{
    const vt::AssertHandler previous = vt::setAssertHandler(nullptr);
    ::testing::internal::CaptureStderr();
    const int line = __LINE__ + 1;
    VT_ASSERT(false, (void)0);
    const std::string text = ::testing::internal::GetCapturedStderr();
    vt::setAssertHandler(previous);
    EXPECT_NE(text.find("\"false\""), std::string::npos) << text;
    EXPECT_NE(text.find("vt_assert_test.cpp:" + std::to_string(line)), std::string::npos) << text;
}

} // namespace
