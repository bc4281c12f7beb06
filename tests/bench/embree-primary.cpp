// The yardstick of compare-embree.sh: Embree 3's rtcIntersect1 alone (no shading) on the camera
// rays of tests/bench/make-bench-scenes.py's mesh-N-primary scene. Built by that script only.
//
//   embree-primary MESH.obj THREADS RUNS   prints one "ms" line per run
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: embree-primary MESH.obj THREADS RUNS\n");
        return 2;
    }
    std::vector<float> v;
    std::vector<unsigned> f;
    std::ifstream in(argv[1]);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            float x, y, z;
            s >> x >> y >> z;
            // The scene's transform: scale 2, then translate (0, 1.2, 0).
            v.insert(v.end(), {2.0f * x, 2.0f * y + 1.2f, 2.0f * z});
        } else if (tag == "f") {
            unsigned a, b, c;
            s >> a >> b >> c;
            f.insert(f.end(), {a - 1, b - 1, c - 1});
        }
    }
    v.resize(v.size() + 4);  // Embree may load 16 bytes at the last vertex
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, v.data(), 0,
                               3 * sizeof(float), (v.size() - 4) / 3);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, f.data(), 0,
                               3 * sizeof(unsigned), f.size() / 3);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);

    // The camera of the scene file: position (0, 1.5, 4.2), target (0, 1.2, 0), fov_y 50.
    const int W = 1280, H = 720;
    const float px = 0, py = 1.5f, pz = 4.2f;
    float fx = 0 - px, fy = 1.2f - py, fz = 0 - pz;
    const float fl = std::sqrt(fx * fx + fy * fy + fz * fz);
    fx /= fl, fy /= fl, fz /= fl;
    float rx = -fz, ry = 0, rz = fx;  // forward x up(0,1,0)
    const float rl = std::sqrt(rx * rx + rz * rz);
    rx /= rl, rz /= rl;
    const float ux = ry * fz - rz * fy, uy = rz * fx - rx * fz, uz = rx * fy - ry * fx;
    const float hh = std::tan(50.0f * 3.14159265f / 360.0f), hw = hh * float(W) / float(H);

    tbb::task_arena arena(std::atoi(argv[2]));
    const int runs = std::atoi(argv[3]);
    for (int run = 0; run < runs; ++run) {
        std::vector<unsigned> hits(H, 0);
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& r) {
                RTCIntersectContext context;
                rtcInitIntersectContext(&context);
                for (int y = r.begin(); y != r.end(); ++y) {
                    for (int x = 0; x < W; ++x) {
                        const float u = (2.0f * (float(x) + 0.5f) / float(W) - 1.0f) * hw;
                        const float w = (1.0f - 2.0f * (float(y) + 0.5f) / float(H)) * hh;
                        float dx = fx + rx * u + ux * w, dy = fy + ry * u + uy * w,
                              dz = fz + rz * u + uz * w;
                        const float dl = std::sqrt(dx * dx + dy * dy + dz * dz);
                        RTCRayHit rh;
                        rh.ray.org_x = px, rh.ray.org_y = py, rh.ray.org_z = pz;
                        rh.ray.dir_x = dx / dl, rh.ray.dir_y = dy / dl, rh.ray.dir_z = dz / dl;
                        rh.ray.tnear = 0.0f;
                        rh.ray.tfar = INFINITY;
                        rh.ray.mask = ~0u;
                        rh.ray.flags = 0;
                        rh.ray.time = 0.0f;
                        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(scene, &context, &rh);
                        hits[std::size_t(y)] += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                    }
                }
            });
        });
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        unsigned total = 0;
        for (unsigned h : hits) total += h;
        std::printf("%.3f %u\n", ms, total);
    }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
