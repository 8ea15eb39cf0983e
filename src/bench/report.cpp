#include "bench/report.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace impossible::bench {
namespace {

using nlohmann::json;

// A finite number, or null (PSNR of identical pictures is +infinity).
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json config_json(const ConfigResult& r, double base_median) {
    const Spread frame = spread_of(r.frame_ms), submit = spread_of(r.submit_ms);
    json j;
    j["name"] = r.config.name;
    j["group"] = r.config.group;
    if (!r.error.empty()) {
        j["error"] = r.error;
        return j;
    }
    const render::FrameDesc& f = r.config.frame;
    j["eye_width"] = f.eye_width;
    j["eye_height"] = f.eye_height;
    j["max_depth"] = f.max_depth;
    j["samples"] = f.samples;
    j["frames"] = r.frame_ms.size();
    j["frame_ms_median"] = frame.median;
    j["frame_ms_p10"] = frame.p10;
    j["frame_ms_p90"] = frame.p90;
    j["frame_ms_vs_base"] = base_median > 0 ? frame.median / base_median : 0.0;
    j["submit_ms_median"] = submit.median;
    j["profiled_frame_ms_median"] = r.profiled_frame_ms;
    j["fragments_per_pixel"] = r.fragments_per_pixel;
    j["draw_calls"] = r.draw_calls;
    j["triangles"] = r.triangles;
    j["portal_passes_drawn"] = r.portal_passes_drawn;
    j["portal_passes_culled"] = r.portal_passes_culled;
    j["portal_fills"] = r.portal_fills;
    json portals = json::array();
    for (const PortalResult& p : r.portals)
        portals.push_back({{"pose", p.pose},
                           {"portal", p.portal},
                           {"ms_median", p.ms_median},
                           {"fragments_per_pixel", p.fragments_per_pixel}});
    j["portals"] = portals;
    if (r.has_error) {
        j["id_mismatch_percent"] = r.id_mismatch_percent;
        j["worst_id_mismatch_percent"] = r.worst_id_mismatch_percent;
        j["psnr_db"] = number(r.psnr_db);
    }
    return j;
}

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return "inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace

std::string bench_json(const BenchResult& result, const BenchOptions& options) {
    const double base = spread_of(result.configs[0].frame_ms).median;
    json j = config_json(result.configs[0], base);  // the base configuration at the top level
    j["layout"] = options.view.layout_path.value_or("<default>");
    j["gl_renderer"] = result.gl_renderer;
    j["cores"] = result.cores;
    j["poses"] = result.poses;
    j["warmup"] = options.warmup;
    j["profile_frames"] = options.profile_frames;
    if (options.error) j["reference_depth"] = options.reference_depth;
    if (options.error) j["reference_samples"] = options.reference_samples;
    json configs = json::array();
    for (const ConfigResult& r : result.configs) configs.push_back(config_json(r, base));
    j["configs"] = configs;
    return j.dump(2) + "\n";
}

std::string bench_csv(const BenchResult& result) {
    std::string s =
        "name,group,eye_width,eye_height,max_depth,frame_ms_median,frame_ms_p10,frame_ms_p90,frame_ms_vs_base,"
        "submit_ms_median,fragments_per_pixel,draw_calls,triangles,portal_passes_drawn,portal_passes_culled,"
        "portal_fills,id_mismatch_percent,psnr_db\n";
    const double base = spread_of(result.configs[0].frame_ms).median;
    for (const ConfigResult& r : result.configs) {
        if (!r.error.empty()) continue;
        const Spread frame = spread_of(r.frame_ms);
        const render::FrameDesc& f = r.config.frame;
        s += r.config.name + "," + r.config.group + "," + std::to_string(f.eye_width) + "," +
             std::to_string(f.eye_height) + "," + std::to_string(f.max_depth) + "," + fixed(frame.median, 4) + "," +
             fixed(frame.p10, 4) + "," + fixed(frame.p90, 4) + "," + fixed(frame.median / base, 4) + "," +
             fixed(spread_of(r.submit_ms).median, 4) + "," + fixed(r.fragments_per_pixel, 4) + "," +
             fixed(r.draw_calls, 1) + "," + fixed(r.triangles, 1) + "," + fixed(r.portal_passes_drawn, 1) + "," +
             fixed(r.portal_passes_culled, 1) + "," + fixed(r.portal_fills, 1) + "," +
             (r.has_error ? fixed(r.id_mismatch_percent, 4) : "") + "," + (r.has_error ? fixed(r.psnr_db, 2) : "") +
             "\n";
    }
    return s;
}

void write_bench_table(const BenchResult& result, const BenchOptions& options, std::ostream& out) {
    char line[512];
    out << "bench: " << options.view.layout_path.value_or("<default>") << ", " << result.poses << " pose(s), "
        << options.frames << " timed frames each after " << options.warmup << " warm-up, " << result.gl_renderer << ", "
        << result.cores << " cores\n";
    std::snprintf(line, sizeof line, "%-22s %10s %8s %8s %7s %9s %7s %8s %7s %7s %6s %9s %7s\n", "config", "median ms",
                  "p10", "p90", "vs base", "submit ms", "frag/px", "draws", "drawn", "culled", "fills", "id mism%",
                  "PSNR");
    out << line;
    const double base = spread_of(result.configs[0].frame_ms).median;
    for (const ConfigResult& r : result.configs) {
        if (!r.error.empty()) {
            out << r.config.name << ": not measured: " << r.error << "\n";
            continue;
        }
        const Spread frame = spread_of(r.frame_ms);
        std::snprintf(line, sizeof line, "%-22s %10.3f %8.3f %8.3f %7.3f %9.3f %7.3f %8.1f %7.1f %7.1f %6.1f %9s %7s\n",
                      r.config.name.c_str(), frame.median, frame.p10, frame.p90, frame.median / base,
                      spread_of(r.submit_ms).median, r.fragments_per_pixel, r.draw_calls, r.portal_passes_drawn,
                      r.portal_passes_culled, r.portal_fills,
                      r.has_error ? fixed(r.id_mismatch_percent, 4).c_str() : "-",
                      r.has_error ? fixed(r.psnr_db, 2).c_str() : "-");
        out << line;
    }
    const ConfigResult& b = result.configs[0];
    if (!b.portals.empty()) {
        out << "per portal (base; subtree time with glFinish around it, profiled frame "
            << fixed(b.profiled_frame_ms, 3) << " ms):\n";
        for (const PortalResult& p : b.portals) {
            std::snprintf(line, sizeof line, "  pose %-4d %-24s %9.3f ms %7.3f frag/px\n", p.pose, p.portal.c_str(),
                          p.ms_median, p.fragments_per_pixel);
            out << line;
        }
    }
}

}  // namespace impossible::bench
