#pragma once
// The commands of `vectorfluid` (docs/command-line.md). Each returns the process exit code:
// 0 done, 2 bad input (one line on stderr), 3 a limit was hit (what was done so far is written),
// 4 `render --check-topology` found contours crossing (what was done so far is written),
// 130 interrupted by Ctrl+C or SIGTERM (no output written; frames already written stay).
#include <QStringList>

namespace vf::app {

enum ExitCode { Done = 0, BadInput = 2, LimitHit = 3, TopologyBroken = 4, Interrupted = 130 };

int renderCommand(const QStringList& arguments);
int animateCommand(const QStringList& arguments);
int devicesCommand(const QStringList& arguments);
// The desktop app (app/GuiMain.cpp): creates the QApplication, so it takes argc/argv.
int guiMain(int argc, char** argv);

} // namespace vf::app
