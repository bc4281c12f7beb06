// `raystudio-cli validate`: prints ok, or every error of the scene file with its location.
#include "arguments.h"
#include "commands.h"

#include <cstdio>

namespace rs::cli {

int runValidate(int argc, char** argv) {
    Arguments args(argc, argv, 2, OptionSpec{});
    if (args.positional().size() != 1) throw UsageError{"expects exactly one scene file"};
    SceneLoadResult result = loadScene(args.positional()[0]);
    if (!result.ok()) {
        for (const SceneError& e : result.errors) std::printf("%s\n", e.toString().c_str());
        return 2;
    }
    std::printf("ok\n");
    return 0;
}

}  // namespace rs::cli
