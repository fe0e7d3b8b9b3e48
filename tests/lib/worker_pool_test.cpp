// WorkerPool: every task runs once, batches from several threads and nested batches finish.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "fx/worker_pool.h"

namespace {

TEST(WorkerPool, RunsEveryTaskOnce) {
  for (size_t threads : {1u, 2u, 4u}) {
    fx::WorkerPool pool(threads);
    EXPECT_EQ(pool.concurrency(), threads);
    std::vector<std::atomic<int>> hits(1000);
    pool.for_each(hits.size(), [&](size_t i) { hits[i].fetch_add(1); });
    for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
    pool.for_each(0, [](size_t) { FAIL(); });
  }
}

TEST(WorkerPool, NestedBatchesAndSeveralCallersFinish) {
  fx::WorkerPool pool(3);
  std::atomic<int> total{0};
  auto nested = [&] { pool.for_each(8, [&](size_t) { pool.for_each(16, [&](size_t) { total.fetch_add(1); }); }); };
  std::vector<std::thread> callers;
  for (int i = 0; i < 4; ++i) callers.emplace_back(nested);
  for (std::thread& t : callers) t.join();
  EXPECT_EQ(total.load(), 4 * 8 * 16);
}

}  // namespace
