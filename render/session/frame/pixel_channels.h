// The deep frame's per-pixel channels, listed once. DeepFrame declares its buffers from this
// list, and allocation, the bytes a pixel costs, the commit's prefetches and the designer's
// display copy all follow it: a new per-pixel channel is one line here (plus what writes it).
#pragma once

/// RS_DEEP_FRAME_CHANNELS(X) calls X(name, Vector, Type, fresh, ahead, shown) for each
/// channel, one element of Type a pixel, row-major like the frame:
/// - Vector: LargeVector (large blocks) or std::vector, the container of the buffer;
/// - fresh: the value every pixel gets from resize();
/// - ahead: where the channel comes when a whole-tile commit asks for the next row's lines
///   before writing them (1 first, 0 not at all), in the order its loop writes them: lines
///   written first arrive first (in another order that commit took about 40 % longer);
/// - shown: what the designer's display copy does with it (kNotShown, kShown: compared and
///   copied; kShownInDebug: the same while a debug view shows it; kShownAsOverlay: the
///   re-traced overlay's flags, which edits change outside any tile).
///
/// The channels:
/// - color: what is shown (linear HDR);
/// - base: the centre sample when supersampling; adaptive decisions read it;
/// - sampleSum, sampleCount: the running sum of supersamples (progressive refinement);
/// - id: the object seen through the pixel centre; depth: the distance to that hit (infinity:
///   background); normal: its unit normal;
/// - cost: rays traced for the pixel's latest value;
/// - state: a PixelState; flags: PixelFlag bits;
/// - hitBound: bounding sphere (centre, radius) of the pixel's camera-ray hit points, radius
///   < 0 when nothing was hit; shadow-aware dirty regions test segments from it to each light;
/// - recordStart, recordCount: the pixel's deferred shading records in its tile's pool;
/// - segmentStart, segmentCount: the secondary segments of its ray tree in its tile's pool.
#define RS_DEEP_FRAME_CHANNELS(X)                                                         \
    X(color, LargeVector, Color, Color(0.0f), 1, kShown)                                  \
    X(base, LargeVector, Color, Color(0.0f), 0, kNotShown)                                \
    X(sampleSum, LargeVector, Color, Color(0.0f), 0, kNotShown)                           \
    X(sampleCount, LargeVector, uint16_t, uint16_t(0), 0, kNotShown)                      \
    X(id, LargeVector, ObjectId, kNoObject, 3, kShown)                                    \
    X(depth, LargeVector, float, kInfinity, 4, kShown)                                    \
    X(normal, LargeVector, Vec3, Vec3(0.0f), 5, kShownInDebug)                            \
    X(cost, LargeVector, uint32_t, uint32_t(0), 2, kShownInDebug)                         \
    X(state, LargeVector, uint8_t, uint8_t(kStale), 8, kNotShown)                         \
    X(flags, LargeVector, uint8_t, uint8_t(0), 7, kShownAsOverlay)                        \
    X(hitBound, LargeVector, glm::vec4, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f), 6, kNotShown) \
    X(recordStart, std::vector, uint32_t, uint32_t(0), 0, kNotShown)                      \
    X(recordCount, std::vector, uint8_t, uint8_t(0), 0, kNotShown)                        \
    X(segmentStart, std::vector, uint32_t, uint32_t(0), 9, kNotShown)                     \
    X(segmentCount, std::vector, uint8_t, uint8_t(0), 10, kNotShown)
