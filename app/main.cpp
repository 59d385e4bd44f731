// ppr: pixel-projected reflections sample. See README.md and `ppr --help`.
#include "bench/bench.hpp"
#include "capture/capture.hpp"
#include "cli/cli.hpp"
#include "compare/compare.hpp"
#include "fit/fit.hpp"
#include "viewer/viewer.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
    using namespace ppr::app;
    try {
        Options o = parseCommandLine(argc, argv);
        if (o.help) {
            std::fputs(usage().c_str(), stdout);
            return 0;
        }
        if (o.mode == Mode::Auto) o.mode = displayAvailable() ? Mode::View : Mode::Capture;
        if (o.mode == Mode::View) return runViewer(o);
        if (o.mode == Mode::Compare) return runCompare(o);
        if (o.mode == Mode::Bench) return runBench(o);
        if (o.mode == Mode::Fit) return runFit(o);
        return runCapture(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ppr: error: %s\n", e.what());
        return 2;
    }
}
