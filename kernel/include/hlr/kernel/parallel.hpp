// hlr kernel, parallel loops: oneTBB over chunks of an index range, run inline when the range is
// one chunk, so that a small scene does not pay for starting the scheduler; from scene import up
// (hlr/hidden_line/parallel.hpp brings them into hidden_line). Callers process each index on its
// own, so results never depend on the number of threads. Each call of the body gets at most
// `grain` indices (oneTBB's simple partitioner; its default one may hand a thread a large share of
// the whole range at once), so that a stop polled once per call takes effect soon.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

namespace hlr {

template <class Body>
void parallel_chunks(std::size_t size, std::size_t grain, const Body& body) {
  const tbb::blocked_range<std::size_t> all(0, size, grain);
  if (size <= grain) body(all);
  else tbb::parallel_for(all, body, tbb::simple_partitioner());
}

// Calls body(begin, end) for the chunks [k grain, (k + 1) grain) of [0, size): at those bounds,
// so that a caller may keep a result per chunk at begin / grain.
template <class Body>
void aligned_chunks(std::size_t size, std::size_t grain, const Body& body) {
  parallel_chunks((size + grain - 1) / grain, 1, [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) body(k * grain, std::min(size, (k + 1) * grain));
  });
}

// Empties `v` and frees its memory, the elements on every thread: a large stage's data (lazy
// exact numbers by the million) takes a while to free on one.
template <class T>
void free_in_parallel(std::vector<T>& v) {
  parallel_chunks(v.size(), 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) v[i] = {};
  });
  std::vector<T>().swap(v);
}

// free_in_parallel for arrays kept per mesh: a scene of one mesh holds them all in one.
template <class T>
void free_each_in_parallel(std::vector<std::vector<T>>& vs) {
  for (auto& v : vs) free_in_parallel(v);
  std::vector<std::vector<T>>().swap(vs);
}

// Resizes `v` to n value-initialized elements, the pages of its new room first written on every
// thread: in a large drawing an array's fresh pages cost more than filling it does (a page fault
// each), and faults on two threads overlap. (The bytes are written before the elements are made
// there: storage the vector owns and no element lives in yet.)
template <class T>
void resize_in_parallel(std::vector<T>& v, std::size_t n) {
  if (n <= v.size()) {
    v.resize(n);
    return;
  }
  v.reserve(n);
  auto* room = reinterpret_cast<unsigned char*>(v.data() + v.size());
  const std::size_t bytes = (n - v.size()) * sizeof(T);
  constexpr std::size_t kChunk = std::size_t(1) << 20;
  parallel_chunks((bytes + kChunk - 1) / kChunk, 1, [&](const auto& range) {
    for (std::size_t c = range.begin(); c != range.end(); ++c)
      std::memset(room + c * kChunk, 0, std::min(kChunk, bytes - c * kChunk));
  });
  v.resize(n);
}

}  // namespace hlr
