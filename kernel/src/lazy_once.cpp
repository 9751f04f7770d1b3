// pthread_once for hlr's own objects, linked in place of glibc's with `--wrap=pthread_once`
// (kernel/CMakeLists.txt): it makes a system call only when a thread waits.
//
// Why: an Epeck lazy number computes its exact value once, under std::call_once, which libstdc++
// (GCC 12) runs through pthread_once; glibc's pthread_once ends every first call with a futex wake
// system call whether or not a thread waits. That costs about 1 µs on this project's machines, more
// than the arithmetic of most nodes, and an exact drawing's output stage rounds through hundreds of
// nodes a part (docs/BENCHMARKS.md, "Eighteenth run"). Only the calls in objects linked with the
// option come here (every pthread_once call in hlr is std::call_once inlined from the headers);
// glibc and the other libraries keep their own, and no flag is shared between the two.
#include <pthread.h>

#include <atomic>
#include <climits>

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

// A flag's states (PTHREAD_ONCE_INIT is 0).
constexpr int kIdle = 0;
constexpr int kRunning = 1;
constexpr int kRunningWaited = 2;  // running, and some thread sleeps on the flag
constexpr int kDone = 3;

void wake_all(int* flag) { syscall(SYS_futex, flag, FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0); }
void sleep_while(int* flag, int state) { syscall(SYS_futex, flag, FUTEX_WAIT_PRIVATE, state, nullptr, nullptr, 0); }

// Ends a run: the flag to `state`, and the sleepers woken only if there are any.
void finish(std::atomic_ref<int> flag, int* raw, int state) {
  if (flag.exchange(state, std::memory_order_release) == kRunningWaited) wake_all(raw);
}

}  // namespace

extern "C" int __wrap_pthread_once(pthread_once_t* control, void (*init)(void)) {
  static_assert(sizeof(pthread_once_t) == sizeof(int));
  int* raw = reinterpret_cast<int*>(control);
  std::atomic_ref<int> flag(*raw);
  for (;;) {
    int state = flag.load(std::memory_order_acquire);
    if (state == kDone) return 0;
    if (state == kIdle) {
      if (!flag.compare_exchange_strong(state, kRunning, std::memory_order_acquire)) continue;
      try {
        init();
      } catch (...) {  // std::call_once: a call that throws leaves the flag for the next caller
        finish(flag, raw, kIdle);
        throw;
      }
      finish(flag, raw, kDone);
      return 0;
    }
    if (state == kRunning &&
        !flag.compare_exchange_strong(state, kRunningWaited, std::memory_order_relaxed))
      continue;
    sleep_while(raw, kRunningWaited);
  }
}
