// raystudio-cli entry point: dispatches to the sub-commands and maps failures to exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "arguments.h"
#include "commands.h"
#include "core/failure_message.h"
#include "raystudio_version.h"

namespace {

const char* const kUsage =
    "usage: raystudio-cli <command> [options]\n"
    "\n"
    "       raystudio-cli --version\n"
    "\n"
    "commands:\n"
    "  render SCENE -o OUT [--width W] [--height H] [--max-depth D] [--min-weight W]\n"
    "                      [--shadow-samples N] [--supersampling N] [--threads N] [--stats]\n"
    "                      [--engine embree|builtin] [--force] [--view NAME]\n"
    "      render a scene file to an image (PNG, JPEG, TIFF, EXR, HDR by extension); renders\n"
    "      estimated over the cost budget (1e11 rays, 8 GiB of frame) need --force;\n"
    "      --view looks through one of the scene's views instead of its camera\n"
    "  validate SCENE\n"
    "      check a scene file; prints 'ok', or every error found on stderr (exit 2), or its\n"
    "      warnings (images that cannot be read: exit 1)\n"
    "  bench SCENE [--repeat N] [--json] [--threads N] [--width W] [--height H]\n"
    "              [--min-weight W] [--engine embree|builtin] [--baseline-only]\n"
    "      the thesis's chapter 4.2 experiments (shadow samples, depth, supersampling);\n"
    "      --baseline-only times the scene as it is, N times in one process\n"
    "  drag SCENE --object NAME --to X,Y,Z [--steps N] [--policy default|none|FILE]\n"
    "             [--threads N] [--verify] [--json] [--width W] [--height H] [--max-depth D]\n"
    "             [--min-weight W] [--shadow-samples N] [--supersampling N]\n"
    "             [--engine embree|builtin] [--frames N]\n"
    "      drag an object through the interactive session, refine, compare with a full render\n"
    "  render SCENE --tile I/N -o PART.exr [--ids] [render options]\n"
    "      render part I of N (0-based band of rows) into a linear EXR that records its place\n"
    "      in the image and a fingerprint of the scene and settings\n"
    "  merge PART... -o OUT\n"
    "      merge every part of one render into OUT, bit-identical to a one-machine render;\n"
    "      refuses missing, doubled and foreign parts\n"
    "  farm submit SCENE -o OUT --parts N [--partition P] [--time T] [--cpus-per-task C]\n"
    "              [--dry-run] [render options]\n"
    "      render on a Slurm cluster: a job array of N parts and a merge job (sbatch)\n"
    "  farm status JOB\n"
    "      progress of a submitted job (squeue, sacct)\n"
    "  import ASSET -o SCENE [--width W] [--height H] [--flat-normals] [--camera frame|asset]\n"
    "      a scene holding the asset (glTF, OBJ, FBX, ...) with its materials and textures\n"
    "      (embedded images written next to SCENE), its lights (a key light when it has\n"
    "      none), its cameras as views, and a camera that frames it (asset: the asset's\n"
    "      first camera)\n"
    "\n"
    "results go to stdout, errors to stderr; exit codes: 0 success, 2 bad input or usage,\n"
    "1 any other failure\n";

/// True when an argument after the command asks for help.
bool asksForHelp(int argc, char** argv) {
    for (int i = 2; i < argc; ++i)
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) return true;
    return false;
}

/// The usage of one command: the entries of kUsage that begin with it (render has two).
std::string commandUsage(const std::string& command) {
    std::string out, line;
    bool inEntry = false;
    for (const char* p = kUsage; *p; ++p) {
        line += *p;
        if (*p != '\n') continue;
        // An entry starts "  NAME " and goes on with lines indented further.
        const bool header = line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ';
        if (header)
            inEntry = line.compare(2, command.size() + 1, command + " ") == 0 ||
                      line.compare(2, command.size() + 1, command + "\n") == 0;
        else if (line.compare(0, 3, "   ") != 0)
            inEntry = false;
        if (inEntry) out += line;
        line.clear();
    }
    return out.empty() ? std::string() : "usage: raystudio-cli\n" + out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::string command = argv[1];
    if (asksForHelp(argc, argv)) {
        const std::string usage = commandUsage(command);
        if (!usage.empty()) {
            std::fputs(usage.c_str(), stdout);
            return 0;
        }
    }
    try {
        if (command == "render") return rs::cli::runRender(argc, argv);
        if (command == "validate") return rs::cli::runValidate(argc, argv);
        if (command == "bench") return rs::cli::runBench(argc, argv);
        if (command == "drag") return rs::cli::runDrag(argc, argv);
        if (command == "merge") return rs::cli::runMerge(argc, argv);
        if (command == "farm") return rs::cli::runFarm(argc, argv);
        if (command == "import") return rs::cli::runImport(argc, argv);
        if (command == "--version") {
            std::puts("raystudio-cli " RAYSTUDIO_VERSION_STRING);
            return 0;
        }
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        std::fprintf(stderr, "raystudio-cli: unknown command '%s'\n\n%s", command.c_str(), kUsage);
        return 2;
    } catch (const rs::cli::UsageError& e) {
        std::fprintf(stderr, "raystudio-cli %s: %s\n", command.c_str(), e.message.c_str());
        return 2;
    } catch (...) {
        std::fprintf(stderr, "raystudio-cli %s: %s\n", command.c_str(),
                     rs::describeFailure(std::current_exception()).c_str());
        return 1;
    }
}
