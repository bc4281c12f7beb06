// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <unistd.h>

#include <cstdio>

namespace rs::cli {

/// Redraws "[#####.....]  42%" in place; silent when stderr is not a terminal.
class ProgressBar {
public:
    ProgressBar() : enabled_(isatty(STDERR_FILENO) != 0) {}
    void update(int done, int total) {
        if (!enabled_ || total <= 0) return;
        const int percent = done * 100 / total;
        if (percent == last_) return;
        last_ = percent;
        const int filled = percent * kWidth / 100;
        std::fprintf(stderr, "\r[");
        for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : '.', stderr);
        std::fprintf(stderr, "] %3d%%", percent);
        if (done == total) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    static constexpr int kWidth = 40;
    bool enabled_;
    int last_ = -1;
};

}  // namespace rs::cli
