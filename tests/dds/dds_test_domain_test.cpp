// The DDS tests' domains: concurrently running test processes must never share one, or a
// test hears another's participants (a clean-clone CI run counted three refused peers in
// a security test whose only intruder was one: a neighbouring test's, in the same domain).

#include "dds_test_support.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>

namespace mhd::dds::test {
namespace {

TEST(TestDomains, TwoReservationsWhoseFirstChoicesCollideGetDifferentDomains) {
  // Salts 0 and 200 give the same first choice (the pid hash is taken modulo 200).
  const std::uint32_t a = use_loopback_and_unique_domain(0);
  const std::uint32_t b = use_loopback_and_unique_domain(200);
  EXPECT_NE(a, b);
  EXPECT_GE(a, 1u);
  EXPECT_LE(a, 200u);
  EXPECT_GE(b, 1u);
  EXPECT_LE(b, 200u);
}

TEST(TestDomains, ADomainHeldByAnotherProcessIsNotTakenAndIsTakenOnceFreed) {
  int to_parent[2];
  int to_child[2];
  ASSERT_EQ(pipe(to_parent), 0);
  ASSERT_EQ(pipe(to_child), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::uint32_t held = reserve_test_domain(157);
    (void)!write(to_parent[1], &held, sizeof held);
    char go = 0;
    (void)!read(to_child[0], &go, 1);  // hold it until the parent has tried
    _exit(0);
  }
  std::uint32_t held_by_child = 0;
  ASSERT_EQ(read(to_parent[0], &held_by_child, sizeof held_by_child), static_cast<ssize_t>(sizeof held_by_child));
  ASSERT_EQ(held_by_child, 157u) << "a free first choice is taken";
  EXPECT_NE(reserve_test_domain(157), 157u) << "the child still holds 157";
  const char go = 1;
  ASSERT_EQ(write(to_child[1], &go, 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_EQ(reserve_test_domain(157), 157u) << "a process's domains are freed when it ends";
}

}  // namespace
}  // namespace mhd::dds::test
