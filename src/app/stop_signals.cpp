#include "app/stop_signals.h"

#include <signal.h>

#include <atomic>

namespace fastshade {

namespace {

std::atomic<int> g_received{0};  // lock-free, so a signal handler may store to it
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int, g_previous_term;

void on_stop_signal(int signal) { g_received.store(signal); }

}  // namespace

StopSignals::StopSignals() {
  g_received.store(0);
  struct sigaction action = {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal takes the default action: terminate
  ::sigaction(SIGINT, &action, &g_previous_int);
  ::sigaction(SIGTERM, &action, &g_previous_term);
}

StopSignals::~StopSignals() {
  ::sigaction(SIGINT, &g_previous_int, nullptr);
  ::sigaction(SIGTERM, &g_previous_term, nullptr);
}

int StopSignals::received() { return g_received.load(std::memory_order_relaxed); }

}  // namespace fastshade
