// The designer's tools behind the public API: generate, plan, tour.
#include "api/api_data.hpp"
#include "base/format.hpp"
#include "design/generate.hpp"
#include "design/plan.hpp"
#include "design/report.hpp"
#include "design/tour.hpp"
#include "math/polygon.hpp"

namespace impossible::api {

Expected<std::string> generate(const GenerateRequest& request) {
    return no_throw([&]() -> Expected<std::string> {
        design::GenerateOptions options;
        if (request.play_area.empty()) {
            const double w = request.width, d = request.depth;
            if (!(w >= 1.0 && w <= 1000.0 && d >= 1.0 && d <= 1000.0))
                return Error{"each side of the play area must be 1..1000 m (got " + format_number(w) + " by " +
                             format_number(d) + ")"};
            options.rectangle = true;
            options.play_area = math::rectangle({-w / 2, -d / 2}, {w / 2, d / 2});
        } else {
            // Its limits are design::generate's, the command's too.
            for (const auto& [x, z] : request.play_area) options.play_area.push_back({x, z});
        }
        if (request.rooms < 1 || request.rooms > design::kMaxGeneratedRooms)
            return Error{"rooms must be 1.." + std::to_string(design::kMaxGeneratedRooms)};
        if (request.max_overlap && !(*request.max_overlap >= 0.0 && *request.max_overlap <= 100.0))
            return Error{"max_overlap must be 0..100 %"};
        options.rooms = request.rooms;
        options.seed = request.seed;
        options.max_overlap = request.max_overlap;
        return expected(design::generate_layout(options));
    });
}

Expected<std::string> plan_svg(const Layout& layout, const std::vector<Pose>& path) {
    return no_throw([&]() -> Expected<std::string> {
        const layout::Layout& l = layout.data().layout;
        std::vector<math::HeadPose> poses;
        for (const Pose& p : path) poses.push_back(to_head_pose(p));
        const design::Report report = design::make_report(l);
        const design::Drawing drawing = design::plan_drawing(l, report, poses);
        return design::plan_svg(drawing, design::plan_scale(drawing, 1200));
    });
}

Expected<std::vector<Pose>> tour(const Layout& layout, const TourRequest& request) {
    return no_throw([&]() -> Expected<std::vector<Pose>> {
        if (!(request.step >= 0.005 && request.step <= 1.0)) return Error{"step must be in 0.005..1 m"};
        if (!(request.head_height >= 0.2 && request.head_height <= 3.0))
            return Error{"head_height must be in 0.2..3 m"};
        design::TourOptions options;
        options.step = request.step;
        options.grid.head_height = request.head_height;
        Result<design::Tour> planned = design::plan_tour(layout.data().layout, options);
        if (!planned) return Error{planned.error()};
        std::vector<Pose> poses;
        for (const math::HeadPose& h : planned->poses) poses.push_back(to_pose(h));
        return poses;
    });
}

}  // namespace impossible::api
