// The pthread_once that hlr's objects are linked with (kernel/src/lazy_once.cpp): std::call_once's
// guarantees under racing threads and throwing calls, and Epeck's lazy numbers on top of it.
#include <hlr/kernel/kernel.hpp>

#include <gtest/gtest.h>

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <algorithm>
#include <random>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <vector>

extern "C" int __wrap_pthread_once(pthread_once_t*, void (*)(void));

namespace {

TEST(LazyOnce, CallOnceRunsThroughTheWrapper) {
  // The link option redirects this object's references, as it does the library's.
  EXPECT_EQ(reinterpret_cast<void*>(&pthread_once), reinterpret_cast<void*>(&__wrap_pthread_once));
}

TEST(LazyOnce, EachFlagRunsOnceUnderRacingThreads) {
  constexpr int kFlags = 4000, kThreads = 4;
  std::vector<std::once_flag> flags(kFlags);
  std::vector<std::atomic<int>> runs(kFlags);
  std::vector<int> value(kFlags, 0);  // written by the one run, read by every caller after it
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      std::mt19937 random(t);
      std::vector<int> order(kFlags);
      for (int i = 0; i < kFlags; ++i) order[i] = i;
      std::shuffle(order.begin(), order.end(), random);
      for (int i : order) {
        std::call_once(flags[i], [&] {
          runs[i].fetch_add(1);
          if (i % 97 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));  // let others wait
          value[i] = i + 1;
        });
        if (value[i] != i + 1) wrong.fetch_add(1);
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(wrong.load(), 0);
  for (int i = 0; i < kFlags; ++i) ASSERT_EQ(runs[i].load(), 1) << "flag " << i;
}

TEST(LazyOnce, AThrowingCallLeavesTheFlagToTheNextCaller) {
  std::once_flag flag;
  EXPECT_THROW(std::call_once(flag, [] { throw std::runtime_error("first"); }), std::runtime_error);
  int runs = 0;
  std::call_once(flag, [&] { ++runs; });
  std::call_once(flag, [&] { ++runs; });
  EXPECT_EQ(runs, 1);

  // A caller waiting on a run that throws is woken, and runs its own call.
  std::once_flag shared;
  std::atomic<bool> running{false};
  std::atomic<int> second_runs{0};
  std::thread first([&] {
    EXPECT_THROW(std::call_once(shared,
                                [&] {
                                  running = true;
                                  std::this_thread::sleep_for(std::chrono::milliseconds(50));
                                  throw std::runtime_error("late");
                                }),
                 std::runtime_error);
  });
  while (!running) std::this_thread::yield();
  std::call_once(shared, [&] { second_runs.fetch_add(1); });
  first.join();
  EXPECT_EQ(second_runs.load(), 1);
}

TEST(LazyOnce, LazyNumbersEvaluatedFromTwoThreadsAgree) {
  using FT = hlr::ExactKernel::FT;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1e3, 1e3);
  // Shared subexpressions, so that both threads reach the same nodes.
  std::vector<FT> inputs;
  for (int i = 0; i < 64; ++i) inputs.emplace_back(coordinate(random));
  std::vector<FT> sums;
  for (int i = 0; i + 3 < 64; ++i) sums.push_back((inputs[i] + inputs[i + 1]) / (inputs[i + 2] * inputs[i + 3] + 1));
  std::vector<FT> expressions;
  for (std::size_t i = 0; i + 1 < sums.size(); ++i) expressions.push_back(sums[i] * sums[i + 1] - sums[i] / 3);

  using ET = std::decay_t<decltype(expressions[0].exact())>;
  std::vector<ET> from_a(expressions.size()), from_b(expressions.size());
  std::thread a([&] { for (std::size_t i = 0; i < expressions.size(); ++i) from_a[i] = expressions[i].exact(); });
  std::thread b([&] { for (std::size_t i = expressions.size(); i-- > 0;) from_b[i] = expressions[i].exact(); });
  a.join();
  b.join();
  for (std::size_t i = 0; i < expressions.size(); ++i) {
    const auto& x = inputs;
    auto e = [&](std::size_t k) -> ET { return x[k].exact(); };
    const ET s0 = (e(i) + e(i + 1)) / (e(i + 2) * e(i + 3) + 1);
    const ET s1 = (e(i + 1) + e(i + 2)) / (e(i + 3) * e(i + 4) + 1);
    EXPECT_EQ(from_a[i], ET(s0 * s1 - s0 / 3)) << i;
    EXPECT_EQ(from_b[i], from_a[i]) << i;
  }
}

}  // namespace
