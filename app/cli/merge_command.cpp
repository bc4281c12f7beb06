// `raystudio-cli merge`: part files of one render (render --tile I/N) into the final image.
#include <cstdio>
#include <sstream>

#include "arguments.h"
#include "commands.h"
#include "image/image_io.h"
#include "image/part_merge.h"

namespace rs::cli {

int runMerge(int argc, char** argv) {
    OptionSpec spec;
    spec.valued = {"--output"};
    spec.aliases = {{"-o", "--output"}};
    Arguments args(argc, argv, 2, spec);
    if (args.positional().empty())
        throw UsageError{"expects the part files (merge PART... -o OUT)"};
    auto output = args.value("--output");
    if (!output || output->empty()) throw UsageError{"missing -o OUT (the image to write)"};
    if (std::string bad = imageFormatError(*output); !bad.empty()) throw UsageError{bad};

    MergedImage merged;
    std::string error;
    if (!mergeParts(args.positional(), merged, error)) {
        std::istringstream lines(error);
        for (std::string line; std::getline(lines, line);)
            std::fprintf(stderr, "raystudio-cli merge: %s\n", line.c_str());
        return 2;
    }
    if (!writeImage(*output, merged.image, merged.header.tonemap, merged.header.exposure, error)) {
        std::fprintf(stderr, "raystudio-cli merge: %s\n", error.c_str());
        return 2;
    }
    std::printf("merged %d parts (%dx%d) into %s\n", merged.header.part.count,
                merged.header.fullWidth, merged.header.fullHeight, output->c_str());
    return 0;
}

}  // namespace rs::cli
