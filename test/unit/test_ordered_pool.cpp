// Unit tests for the ordered thread pool behind -j.
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <stdexcept>
#include <thread>

#include "concurrency/ordered_pool.hpp"

TEST(OrderedPool, ResultsComeBackInSubmissionOrder) {
  for (unsigned threads : {1u, 2u, 4u}) {
    std::vector<int> out;
    {
      tk::OrderedPool<int, int> pool(
          threads,
          [](int& job) {
            std::this_thread::sleep_for(std::chrono::microseconds((job * 7919) % 300));
            return job * 2;
          },
          [&](int& result) { out.push_back(result); });
      for (int i = 0; i < 500; ++i) pool.submit(i);
      pool.finish();
    }
    ASSERT_EQ(out.size(), 500u);
    for (int i = 0; i < 500; ++i) ASSERT_EQ(out[i], 2 * i) << threads;
  }
}

TEST(OrderedPool, AnErrorArrivesAfterEveryEarlierResult) {
  std::vector<int> out;
  tk::OrderedPool<int, int> pool(
      3,
      [](int& job) {
        if (job == 50) throw std::runtime_error("bad job");
        return job;
      },
      [&](int& result) { out.push_back(result); });
  bool caught = false;
  try {
    for (int i = 0; i < 100; ++i) pool.submit(i);
    pool.finish();
  } catch (const std::runtime_error&) {
    caught = true;
  }
  EXPECT_TRUE(caught);
  ASSERT_EQ(out.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(out[i], i);
}
