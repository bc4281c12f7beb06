// `raystudio-cli validate`: prints ok, or every error of the scene file with its location.
#include <cstdio>

#include "arguments.h"
#include "commands.h"

namespace rs::cli {

int runValidate(int argc, char** argv) {
    Arguments args(argc, argv, 2, OptionSpec{});
    if (args.positional().size() != 1) throw UsageError{"expects exactly one scene file"};
    // Errors go to stderr like every command's; stdout carries only the verdict "ok".
    SceneDocument doc;
    if (!loadSceneOrReport(args.positional()[0], doc)) return 2;
    std::printf("ok\n");
    return 0;
}

}  // namespace rs::cli
