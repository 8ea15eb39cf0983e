// time_layout LAYOUT [RUNS]: the median wall time, over RUNS (default 5), of
// the three CPU stages a large layout goes through, for
// bench/large-layouts.sh: load (parse and check the file), report (the
// designer's report that `validate` prints: placement, overlaps, play area)
// and scene (the meshes and portal links the renderer and tracer draw).
// Prints one line: "rooms portals load_ms report_ms scene_ms".
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "design/report.hpp"
#include "layout/layout.hpp"
#include "scene/scene.hpp"

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double ms_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

int main(int argc, char** argv) {
    using namespace impossible;
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: time_layout LAYOUT [RUNS]\n";
        return 2;
    }
    const int runs = argc == 3 ? std::max(1, std::atoi(argv[2])) : 5;
    std::vector<double> load, report, scene;
    std::size_t rooms = 0, portals = 0;
    for (int i = 0; i < runs; ++i) {
        auto t = std::chrono::steady_clock::now();
        const layout::LoadResult loaded = layout::load_layout_file(argv[1]);
        load.push_back(ms_since(t));
        if (!loaded.layout) {
            for (const layout::Diagnostic& d : loaded.errors) std::cerr << d.str() << "\n";
            return 1;
        }
        rooms = loaded.layout->rooms.size();
        portals = loaded.layout->portals.size();
        t = std::chrono::steady_clock::now();
        const design::Report r = design::make_report(*loaded.layout);
        report.push_back(ms_since(t));
        t = std::chrono::steady_clock::now();
        const scene::Scene s = scene::build_scene(*loaded.layout);
        scene.push_back(ms_since(t));
        if (r.summary.rooms != static_cast<int>(rooms) || s.cells.size() != rooms) return 1;
    }
    std::cout << rooms << " " << portals << " " << median(load) << " " << median(report) << " " << median(scene)
              << "\n";
    return 0;
}
