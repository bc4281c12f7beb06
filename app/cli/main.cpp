// raystudio-cli entry point: dispatches to the sub-commands.
#include <cstdio>

int main() {
    std::fprintf(stderr, "raystudio-cli: not yet implemented\n");
    return 1;
}
