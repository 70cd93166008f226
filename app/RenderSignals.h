#pragma once
// The signals a headless render answers itself: Ctrl+C (SIGINT) and SIGTERM stop the run between
// steps, so that nothing half-done is written; SIGXFSZ (a file over `ulimit -f`) is ignored, so
// the write fails with EFBIG and the run says so instead of dying with a core.
namespace vf::app {

void handleRenderSignals();

// Whether SIGINT or SIGTERM came since handleRenderSignals().
bool interruptRequested();

} // namespace vf::app
