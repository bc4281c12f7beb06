// Nothing hangs, nothing terminates: a session whose frame cannot be allocated (too large for
// the area limit, or a bad_alloc under an address-space limit) reports the error through its
// observer, keeps its document and renders again after the next edit; so does one whose
// update() cannot allocate the new snapshot.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>

#include "session/render_session.h"
#include "test_scenes.h"

namespace rs {
namespace {

using namespace std::chrono_literals;

/// Records errors; waitForError() blocks until one arrives.
class ErrorRecorder : public SessionObserver {
public:
    void error(const std::string& message) override {
        std::lock_guard lock(mutex_);
        errors_.push_back(message);
        cv_.notify_all();
    }
    bool waitForError(std::string* message) {
        std::unique_lock lock(mutex_);
        const bool got = cv_.wait_for(lock, 60s, [&] { return !errors_.empty(); });
        if (got && message) *message = errors_.front();
        return got;
    }

private:
    std::mutex mutex_;
    std::condition_variable cv_;
    std::vector<std::string> errors_;
};

/// Shows `doc`, then a small document: the session must be rendering again.
void expectRendersAfter(RenderSession& session, ErrorRecorder& recorder, SceneDocument doc,
                        const std::string& expectedInMessage) {
    session.update(doc);
    std::string message;
    ASSERT_TRUE(recorder.waitForError(&message));
    EXPECT_NE(message.find(expectedInMessage), std::string::npos) << message;
    // The document is kept: the session still holds the failed one, unchanged.
    ASSERT_TRUE(session.snapshot());
    EXPECT_EQ(session.snapshot()->settings().width, doc.render.width);
    doc.render.width = 32;
    doc.render.height = 24;
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.withFrame([](const DeepFrame& frame, const auto&) {
        EXPECT_EQ(frame.width(), 32);
        EXPECT_EQ(frame.pixelCount(), std::size_t(32 * 24));
    });
}

TEST(SessionFailure, FrameOverAreaLimit_IsRefusedWithMessage_AndSessionKeepsWorking) {
    ErrorRecorder recorder;
    RenderSession session(2);
    session.setObserver(&recorder);
    // Each side is allowed; the area (268 Mpixels) is not.
    expectRendersAfter(session, recorder, test::smallRoom(16384, 16384), "at most 64 Mpixels");
}

/// Death-test child: 1 GiB more address space than the process uses now; the 8000 x 8000
/// frame (64 Mpixels, within the area limit) needs some 5.7 GiB, so its allocation throws.
/// (Unused where sanitizers skip the test below.)
[[noreturn, maybe_unused]] void renderUnderAddressSpaceLimit() {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlimit limit{rlim_t(pages) * rlim_t(4096) + (rlim_t(1) << 30), RLIM_INFINITY};
    if (setrlimit(RLIMIT_AS, &limit) != 0) std::exit(3);
    {
        ErrorRecorder recorder;
        RenderSession session(2);
        session.setObserver(&recorder);
        expectRendersAfter(session, recorder, test::smallRoom(8000, 8000), "out of memory");
    }
    std::exit(::testing::Test::HasFailure() ? 1 : 0);
}

TEST(SessionFailure, BadAllocOfTheFrame_IsReported_AndSessionKeepsWorking) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "sanitizers reserve more address space than the limit allows";
#else
    GTEST_FLAG_SET(death_test_style, "threadsafe");  // A fresh process: no inherited threads.
    EXPECT_EXIT(renderUnderAddressSpaceLimit(), ::testing::ExitedWithCode(0), "");
#endif
}

/// An allocation that fails while the session builds a snapshot (a huge scene, on the
/// session's scheduler thread, where the designer's edits are applied) is reported through
/// the observer; the session keeps what it showed and renders the next edit. The failure is
/// injected as the std::bad_alloc a failed allocation throws (an address-space limit made it
/// depend on how much the rest of the process had allocated).
TEST(SessionFailure, BadAllocInUpdate_IsReported_AndSessionKeepsItsDocument) {
    ErrorRecorder recorder;
    RenderSession session(2);
    session.setObserver(&recorder);
    std::atomic<bool> fail{false};
    session.setSceneUpdater([&fail](const SceneDocument& before,
                                    const std::shared_ptr<const CompiledScene>& snap,
                                    const SceneDocument& after, EngineKind engine) {
        if (fail) throw std::bad_alloc();
        return updateScene(before, snap, after, engine);
    });
    SceneDocument doc = test::smallRoom(32, 24);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    const std::shared_ptr<const CompiledScene> shown = session.snapshot();
    fail = true;
    SceneDocument huge = doc;
    test::addSphere(huge, "one more", Vec3(0.0f, 0.0f, -5.0f), 0.4f, huge.materials.front().name);
    const uint64_t posted = session.update(huge);  // Must return, not throw.
    std::string message;
    ASSERT_TRUE(recorder.waitForError(&message));
    EXPECT_NE(message.find("out of memory"), std::string::npos) << message;
    // The session keeps what it showed: the same snapshot; the failed document never applies.
    EXPECT_FALSE(session.waitForUpdate(posted, 1s));
    EXPECT_EQ(session.snapshot(), shown);
    // And it renders the next edit.
    fail = false;
    doc.render.width = 40;
    ASSERT_TRUE(session.waitForUpdate(session.update(doc), 30s));
    ASSERT_TRUE(session.waitUntilComplete(60s));
    session.withFrame([](const DeepFrame& frame, const auto&) { EXPECT_EQ(frame.width(), 40); });
}

}  // namespace
}  // namespace rs
