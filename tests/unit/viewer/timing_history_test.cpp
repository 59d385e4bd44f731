#include "viewer/timing_history.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using ppr::app::TimingHistory;
using ppr::graph::PassTiming;

TEST(TimingHistory, RowsFollowTheLastFrameAndKeepOnlyItsPasses) {
    TimingHistory history;
    history.add({{"gbuffer", 1.0}, {"ppr.project", 4.0}, {"ppr.reflect", 2.0}});
    history.add({{"gbuffer", 3.0}, {"ppr.project", 6.0}, {"ppr.reflect", 2.0}});
    ASSERT_EQ(history.rows().size(), 3u);
    EXPECT_DOUBLE_EQ(history.rows()[1].medianMs, 5.0);

    // Another technique: its passes replace the old ones in the table.
    history.add({{"gbuffer", 5.0}, {"ssr.march", 7.0}});
    std::vector<TimingHistory::Row> rows = history.rows();
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].name, "gbuffer");
    EXPECT_EQ(rows[0].history, (std::vector<float>{1.0f, 3.0f, 5.0f}));
    EXPECT_EQ(rows[1].name, "ssr.march");
    EXPECT_EQ(rows[1].history, (std::vector<float>{7.0f}));

    // Coming back, a pass starts afresh: its old times are not mixed into the new median.
    history.add({{"gbuffer", 5.0}, {"ppr.project", 10.0}});
    rows = history.rows();
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].history, (std::vector<float>{10.0f}));
    EXPECT_DOUBLE_EQ(rows[1].medianMs, 10.0);
}

TEST(TimingHistory, HistoriesAreBoundedByTheWindowHoweverManyPassesASessionVisits) {
    TimingHistory history;
    for (size_t frame = 0; frame < 3 * TimingHistory::kFrames; ++frame) {
        // Every frame a pass with a new name (as a session cycling settings would produce).
        history.add({{"gbuffer", static_cast<double>(frame)}, {"pass." + std::to_string(frame), 1.0}});
    }
    const std::vector<TimingHistory::Row> rows = history.rows();
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(history.passesHeld(), 2u);
    EXPECT_EQ(rows[0].history.size(), TimingHistory::kFrames);
    EXPECT_EQ(rows[0].history.front(), static_cast<float>(2 * TimingHistory::kFrames));
    EXPECT_EQ(rows[1].history.size(), 1u);
    EXPECT_EQ(history.totals().size(), TimingHistory::kFrames);
}

TEST(TimingHistory, AnEmptyFrameChangesNothing) {
    TimingHistory history;
    history.add({{"gbuffer", 2.0}});
    history.add({});
    ASSERT_EQ(history.rows().size(), 1u);
    EXPECT_EQ(history.rows()[0].history.size(), 1u);
    EXPECT_DOUBLE_EQ(history.totalMedianMs(), 2.0);
}
