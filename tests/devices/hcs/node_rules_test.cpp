// The node's limits, kept out of the codecs: ≤ 8 parameters per read (OPAT manual §2.1), CNT ≤ 16
// (§2.2), address ranges (OPAT manual §2.1, DMA Profinet manual §3.1).
#include "hcs/node_rules.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;

TEST(HcsNodeRules, OpatSec2_1_AtMostEightParametersPerRead)
{
    EXPECT_FALSE(withinReadLimit(0));
    EXPECT_TRUE(withinReadLimit(1));
    EXPECT_TRUE(withinReadLimit(8));
    EXPECT_FALSE(withinReadLimit(9));
}

TEST(HcsNodeRules, SplitReadsIntoBlocks)
{
    // ARCHITECTURE.md "Monitor": the d-block IDs 0x07..0x0D fit one request.
    EXPECT_EQ(splitReads(0x07, 7), (std::vector<ReadBlock>{{0x07, 7}}));
    EXPECT_EQ(splitReads(0x00, 20), (std::vector<ReadBlock>{{0x00, 8}, {0x08, 8}, {0x10, 4}}));
    EXPECT_EQ(splitReads(0x00, 200, 125), (std::vector<ReadBlock>{{0x00, 125}, {125, 75}}));
    EXPECT_TRUE(splitReads(0x10, 0).empty());
    EXPECT_EQ(splitReads(0xFFFE, 10), (std::vector<ReadBlock>{{0xFFFE, 2}}));
    EXPECT_EQ(splitReads(0, 3, 0), (std::vector<ReadBlock>{{0, 1}, {1, 1}, {2, 1}}));
}

TEST(HcsNodeRules, NotesForWhatTheNodeRefuses)
{
    EXPECT_TRUE(nodeRuleNotes(Request{ReadRequest{1, 1, 7, 8}}, Family::Dma).empty());
    EXPECT_EQ(nodeRuleNotes(Request{ReadRequest{1, 1, 7, 9}}, Family::Dma).size(), 1u);
    EXPECT_EQ(nodeRuleNotes(Request{ReadRequest{1, 1, 7, 0}}, Family::Dma).size(), 1u);
    EXPECT_EQ(nodeRuleNotes(Request{WriteRequest{1, 0, 7, 0}}, Family::Dma).size(),
              1u); // DMA SADR 1..32
    EXPECT_TRUE(
        nodeRuleNotes(Request{WriteRequest{1, 0, 7, 0}}, Family::Opat).empty()); // OPAT master
    EXPECT_EQ(nodeRuleNotes(Request{WriteRequest{1, 8, 7, 0}}, Family::Opat).size(),
              1u); // OPAT 0..7
    EXPECT_EQ(
        nodeRuleNotes(Response{ReadResponse{1, 1, std::vector<std::uint16_t>(9)}}, Family::Dma)
            .size(),
        1u);
    EXPECT_EQ(nodeRuleNotes(Response{CyclicResponse{1, 6, 0, 0, 0}}, Family::Dma).size(), 1u);
    EXPECT_EQ(nodeRuleNotes(Response{ExceptionResponse{1, 1, 3, 7}}, Family::Dma).size(), 1u);
    EXPECT_TRUE(nodeRuleNotes(Response{ExceptionResponse{1, 1, 3, 7}}, Family::Opat).empty());
    for (const LocalText &n : nodeRuleNotes(Request{ReadRequest{1, 40, 7, 0}}, Family::Dma))
        EXPECT_TRUE(n.complete());
}
