#pragma once
// The headless commands of `vectorfluid` (DESIGN §3). Each returns the process exit code:
// 0 done, 2 bad input (one line on stderr), 3 a limit was hit (what was done so far is written).
#include <QStringList>

namespace vf::app {

enum ExitCode { Done = 0, BadInput = 2, LimitHit = 3 };

int renderCommand(const QStringList& arguments);
int devicesCommand(const QStringList& arguments);

} // namespace vf::app
