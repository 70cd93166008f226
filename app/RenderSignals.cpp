#include "app/RenderSignals.h"

#include <csignal>

namespace vf::app {

namespace {

volatile std::sig_atomic_t interrupted = 0;

extern "C" void noteInterrupt(int) { interrupted = 1; }

} // namespace

void handleRenderSignals()
{
    std::signal(SIGINT, noteInterrupt);
    std::signal(SIGTERM, noteInterrupt);
    std::signal(SIGXFSZ, SIG_IGN);
}

bool interruptRequested() { return interrupted != 0; }

} // namespace vf::app
