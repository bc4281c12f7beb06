// `raystudio-cli validate`: prints ok, or every error of the scene file with its location
// (status 2), or its warnings (status 1).
#include <cstdio>

#include "arguments.h"
#include "commands.h"

namespace rs::cli {

int runValidate(int argc, char** argv) {
    Arguments args(argc, argv, 2, OptionSpec{});
    if (args.positional().size() != 1) throw UsageError{"expects exactly one scene file"};
    // Errors go to stderr like every command's; stdout carries only the verdict "ok".
    SceneDocument doc;
    bool warned = false;
    if (!loadSceneOrReport(args.positional()[0], doc, &warned)) return 2;
    // Loadable, but something in it will not show as meant (an image that cannot be read).
    if (warned) return 1;
    std::printf("ok\n");
    return 0;
}

}  // namespace rs::cli
