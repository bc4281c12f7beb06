// Qt-free progress interface of the render session; the UI adapts it to queued signals.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rs {

struct PixelRect;

/// Kinds of passes the session runs.
enum class PassKind {
    Interactive,  ///< While dragging, at the interaction policy's quality.
    Base,         ///< Full quality, one sample per pixel (deferred shadows resolved here).
    Supersample,  ///< Progressive supersampling up to the scene's settings.
};

/// One pass, as measured.
struct PassInfo {
    PassKind kind = PassKind::Base;
    uint64_t generation = 0;
    double ms = 0.0;               ///< Wall time of the tiles, first to last.
    double planMs = 0.0;           ///< Time spent deciding the pass (under the lock).
    std::size_t tracedPixels = 0;  ///< Pixels whose camera rays were traced (or resolved).
    std::size_t totalPixels = 0;
    uint64_t rays = 0;
    bool cancelled = false;  ///< An edit arrived mid-pass; its finished tiles were kept.
    int governorLevel = -1;  ///< Level the governor chose, -1 when it is off.
};

/// Receives session events on the session's own threads: keep handlers short and thread-safe.
class SessionObserver {
public:
    virtual ~SessionObserver() = default;
    /// A tile's pixels were written into the frame.
    virtual void tileDone(int x0, int y0, int x1, int y1, uint64_t generation) {
        (void)x0, (void)y0, (void)x1, (void)y1, (void)generation;
    }
    /// A pass finished or was cancelled.
    virtual void passDone(const PassInfo& info) { (void)info; }
    /// Every pixel is final for this generation: the frame equals a full render.
    virtual void frameComplete(uint64_t generation) { (void)generation; }
    /// Work failed (an allocation, an exception in a worker): the session keeps its document
    /// and waits for the next update instead of terminating the process.
    virtual void error(const std::string& message) { (void)message; }
};

}  // namespace rs
