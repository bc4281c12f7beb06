// Display storage made before a frame of a new size comes: the frame is copied into pages
// already written, off the GUI thread's clock (DisplayFrame::adopt, FrameStorageMaker).
#include "display/frame_storage.h"

#include <QElapsedTimer>
#include <QtTest>
#include <algorithm>

#include "adapter/frame_handover.h"
#include "display/display_frame.h"
#include "session/frame/deep_frame.h"

using namespace rs;
using namespace rs::ui;

class FrameStorageTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void adopt_ANewSizeIsCopiedIntoTheStorageMadeBeforeIt();
    void storageMaker_MakesTheLargestSizeAskedFor();
};

namespace rs {
/// The frame's own buffers, to number the pixels by hand.
struct DeepFrameTestAccess {
    static void number(DeepFrame& f, float base) {
        for (std::size_t i = 0; i < f.color_.size(); ++i) {
            f.color_[i] = Color(base + float(i), 0.5f * float(i), 1.0f);
            f.id_[i] = ObjectId(i % 7);
            f.depth_[i] = base + 0.25f * float(i);
            f.flags_[i] = uint8_t(i % 3);
        }
    }
};
}  // namespace rs

/// A deep frame whose every buffer the display copies differs from pixel to pixel.
static DeepFrame numberedFrame(int w, int h, float base) {
    DeepFrame f;
    f.resize(w, h);
    DeepFrameTestAccess::number(f, base);
    return f;
}

static void compareBuffers(const DisplayFrame& d, const DeepFrame& f) {
    QCOMPARE(d.width, f.width());
    QCOMPARE(d.height, f.height());
    QVERIFY(std::equal(d.color.begin(), d.color.end(), f.color().begin(), f.color().end()));
    QVERIFY(std::equal(d.id.begin(), d.id.end(), f.id().begin(), f.id().end()));
    QVERIFY(std::equal(d.depth.begin(), d.depth.end(), f.depth().begin(), f.depth().end()));
    QVERIFY(std::equal(d.flags.begin(), d.flags.end(), f.flags().begin(), f.flags().end()));
}

void FrameStorageTest::adopt_ANewSizeIsCopiedIntoTheStorageMadeBeforeIt() {
    // The GUI thread wrote the first frame of a new size into fresh pages (a stall of up to
    // 340 ms at 1280x976): storage written beforehand on another thread takes the copy.
    DisplayFrame d;
    const DeepFrame small = numberedFrame(4, 3, 0.0f);
    refreshFrame(d, small, {}, false);
    compareBuffers(d, small);
    const uint64_t serial = d.serial;

    FrameStorage room = touchedStorage(64 * 48);
    const Color* color = room.color.data();
    const ObjectId* id = room.id.data();
    const float* depth = room.depth.data();
    const uint8_t* flags = room.flags.data();
    d.adopt(std::move(room));
    compareBuffers(d, small);  // Adopting changes where the frame lives, not what it shows.
    QCOMPARE(d.serial, serial);

    const DeepFrame large = numberedFrame(64, 48, 100.0f);
    refreshFrame(d, large, {}, false);
    compareBuffers(d, large);
    QVERIFY(d.serial > serial);
    QCOMPARE(d.color.data(), color);
    QCOMPARE(d.id.data(), id);
    QCOMPARE(d.depth.data(), depth);
    QCOMPARE(d.flags.data(), flags);

    // Storage smaller than the frame's own room is left alone.
    d.adopt(touchedStorage(16));
    QCOMPARE(d.color.data(), color);
    compareBuffers(d, large);
}

void FrameStorageTest::storageMaker_MakesTheLargestSizeAskedFor() {
    FrameStorageMaker maker;
    const auto takeWithin = [&maker](int ms) {
        QElapsedTimer t;
        t.start();
        FrameStorage s;
        while ((s = maker.take()).pixels == 0 && t.elapsed() < ms) QTest::qWait(5);
        return s;
    };
    maker.request(1000);
    maker.request(3000);  // While the first job runs: made after it.
    const FrameStorage first = takeWithin(5000);
    QVERIFY(first.pixels == 1000 || first.pixels == 3000);
    QCOMPARE(first.color.size(), first.pixels);
    QCOMPARE(first.flags.size(), first.pixels);
    if (first.pixels == 1000) QCOMPARE(takeWithin(5000).pixels, std::size_t(3000));
    maker.request(2000);  // No larger than asked before: nothing is made.
    QCOMPARE(takeWithin(100).pixels, std::size_t(0));
    maker.request(4000);
    const FrameStorage last = takeWithin(5000);
    QCOMPARE(last.pixels, std::size_t(4000));
    QCOMPARE(last.depth.size(), std::size_t(4000));
}

QTEST_MAIN(FrameStorageTest)
#include "frame_storage_test.moc"
