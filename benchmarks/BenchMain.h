#pragma once
// The end of every Google Benchmark main() here: parse the command line (an argument it does not
// know is an error), run the registered benchmarks, report.
#include <benchmark/benchmark.h>

namespace vf::bench {

inline int runRegisteredBenchmarks(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

} // namespace vf::bench
