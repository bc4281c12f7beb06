// The checker's box filter on four points at once. Not a header: texture/checker.cpp compiles
// it twice through core/lane_instances.inl, for AVX2 (RS_LANES_AVX2 defined) and the baseline.
// Each operation is the one scalar code would do (doubles, exact floors, the same order), so
// every lane's answer is bit for bit the one a point alone would get.

constexpr int kWidth = kLaneWidth;  // gatherLanes gives four
typedef double D __attribute__((vector_size(kWidth * sizeof(double))));

inline D splat(double x) {
    return D{} + x;
}

/// floor() of each lane, exact: with AVX one instruction, else core/floor_lanes.h.
inline D floorOf(D x) {
#if defined(RS_LANES_AVX2)
    return D(_mm256_floor_pd(__m256d(x)));
#else
    return floorLanes(x);
#endif
}

/// The +-1 square wave: +1 on cells with an even floor, -1 on odd ones.
inline D squareWave(D c) {
    const D cell = floorOf(c);
    const D parity = cell - 2.0 * floorOf(0.5 * cell);  // 0 or 1, exact in double
    return 1.0 - 2.0 * parity;
}

/// The integral of the square wave from 0 to c: a triangle wave of period 2 between 0 and 1.
inline D squareIntegral(D c) {
    const D m = c - 2.0 * floorOf(0.5 * c) - 1.0;  // in [-1, 1)
    return 1.0 - (m < 0.0 ? -m : m);
}

/// The odd fraction of each lane: see checkerOddFraction. `p` and `h` are the cell-space
/// inputs' three axes, `scale` the cells' side.
inline D oddFractions(const D (&p)[3], const D (&h)[3], D scale) {
    const D inv = 1.0 / scale;
    D numerator = splat(1.0), denominator = splat(1.0);
    for (int axis = 0; axis < 3; ++axis) {
        const D c = p[axis] * inv + kCheckerTolerance;
        const D width = (h[axis] < 0.0 ? -h[axis] : h[axis]) * inv;
        // The average is numerator / denominator: 0 for a coordinate that is not finite or a
        // box wider than kFlatHalfWidth, the point value below kPointHalfWidth (or a NaN
        // width), else the triangle wave's difference over the width.
        const auto finite = (c - c) == 0.0;
        const auto point = !(width >= kPointHalfWidth);
        const auto flat = width >= kFlatHalfWidth;
        const D spread = squareIntegral(c + width) - squareIntegral(c - width);
        const D n = point ? squareWave(c) : flat ? splat(0.0) : spread;
        const D d = point || flat ? splat(1.0) : 2.0 * width;
        numerator *= finite ? n : splat(0.0);
        denominator *= finite ? d : splat(1.0);
    }
    const D odd = 0.5 - 0.5 * (numerator / denominator);
    const auto valid = scale > 0.0 && (scale - scale) == 0.0;
    return valid ? odd : splat(0.0);
}

/// The odd fractions of `count` points, four at a time (the last lanes padded).
inline void oddFractionsOf(std::size_t count, const CheckerPoints& in, float* odd) {
    for (std::size_t first = 0; first < count; first += kWidth) {
        const float* from[7] = {in.px, in.py, in.pz, in.hx, in.hy, in.hz, in.scale};
        D lanes[7];
        for (int a = 0; a < 7; ++a)
            lanes[a] = __builtin_convertvector(gatherLanes(from[a], first, count), D);
        const D p[3] = {lanes[0], lanes[1], lanes[2]}, h[3] = {lanes[3], lanes[4], lanes[5]};
        const D scale = lanes[6];
        const D f = oddFractions(p, h, scale);
        if (first + kWidth <= count) {
            storeLanes(odd + first, __builtin_convertvector(f, FloatLanes));
        } else {
            for (int k = 0; k < kWidth && first + std::size_t(k) < count; ++k)
                odd[first + std::size_t(k)] = float(f[k]);
        }
    }
}
