// Address changes on a live node never put two modules on one address.
#include "model/fold/fold_apply_moves.h"

#include <gtest/gtest.h>
#include <map>

namespace vt::model {
namespace {

// Plays the moves and fails when a module lands on an address another module holds.
std::vector<int> play(const std::vector<AddressChange> &changes,
                      const std::vector<AddressMove> &moves)
{
    std::vector<int> at;
    for (const AddressChange &c : changes)
        at.push_back(c.current);
    for (const AddressMove &m : moves) {
        EXPECT_EQ(at[static_cast<std::size_t>(m.module)], m.from);
        for (std::size_t i = 0; i < at.size(); ++i)
            EXPECT_FALSE(static_cast<int>(i) != m.module && at[i] == m.to)
                << "collision at " << m.to;
        at[static_cast<std::size_t>(m.module)] = m.to;
    }
    return at;
}

TEST(FoldApplyMoves, FreeTargetsMoveDirectly)
{
    const std::vector<AddressChange> changes{{4, 1}, {5, 2}, {6, 3}};
    const auto moves = planAddressMoves(changes);
    ASSERT_TRUE(moves);
    EXPECT_EQ(moves->size(), 3u);
    EXPECT_EQ(play(changes, *moves), (std::vector<int>{1, 2, 3}));
}

TEST(FoldApplyMoves, ChainWaitsForTheHolder)
{
    // Module 0 wants 2, which module 1 holds until it moves on to 3.
    const std::vector<AddressChange> changes{{1, 2}, {2, 3}};
    const auto moves = planAddressMoves(changes);
    ASSERT_TRUE(moves);
    EXPECT_EQ(moves->front(), (AddressMove{1, 2, 3}));
    EXPECT_EQ(play(changes, *moves), (std::vector<int>{2, 3}));
}

TEST(FoldApplyMoves, SwapGoesThroughASpareAddress)
{
    const std::vector<AddressChange> changes{{2, 1}, {1, 2}, {3, 3}};
    const auto moves = planAddressMoves(changes, 1, 32);
    ASSERT_TRUE(moves);
    EXPECT_EQ(moves->size(), 3u);
    EXPECT_EQ(moves->front().to, 32); // parked on the highest spare
    EXPECT_EQ(play(changes, *moves), (std::vector<int>{1, 2, 3}));
}

TEST(FoldApplyMoves, ImpossiblePlansAreRefused)
{
    EXPECT_FALSE(planAddressMoves({{1, 3}, {2, 3}}));       // same target twice
    EXPECT_FALSE(planAddressMoves({{1, 2}, {2, 1}}, 1, 2)); // ring without a spare
    EXPECT_FALSE(planAddressMoves({{4, 2}, {2, 2}}));       // target held by a module that stays
    const auto none = planAddressMoves({{1, 1}, {2, 2}});
    ASSERT_TRUE(none);
    EXPECT_TRUE(none->empty());
}

} // namespace
} // namespace vt::model
