#pragma once
// What a simulated backend's command log must show when its watchdog fired between two
// commands (a host frozen between them): start, the first command, the timeout (zero)
// when the first one expired, the next command, stop.

#include "command_log_file.h"

#include <gtest/gtest.h>

#include <vector>

namespace mhd::test {

inline void expect_timeout_between_two_commands(const std::vector<CommandLogRow>& rows, double timeout_t_s,
                                                double next_command_t_s) {
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[1].event, "command");
  EXPECT_EQ(rows[2].event, "timeout");
  EXPECT_NEAR(rows[2].t_s, timeout_t_s, 1e-6);
  EXPECT_TRUE(rows[2].is_zero());
  EXPECT_EQ(rows[3].event, "command");
  EXPECT_NEAR(rows[3].t_s, next_command_t_s, 1e-6);
  EXPECT_EQ(rows[4].event, "stop");
}

}  // namespace mhd::test
