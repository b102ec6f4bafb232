#include "host/core/planner/path_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cnc::host::planner {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// LinuxCNC tp (blendmath.h): BLEND_ACC_RATIO_TANGENTIAL 0.5 (the normal share: path_limits.hpp). On a spiral
// the two are not orthogonal: half each.
constexpr double kTangentialShare = 0.5;
constexpr double kNormalShareSpiral = 0.5;
// Below this relative radius difference an arc counts as a circle: a blend arc's radii differ by rounding only.
constexpr double kCircleRadiusRelDiff = 1e-9;

// limit / |component|, infinite for a zero component.
double projected(double limit, double component) {
    const double c = std::fabs(component);
    return c > 0.0 ? limit / c : kInfinity;
}

}  // namespace

PathLimits path_limits(const Curve& curve, double feed_mm_per_s, const PlannerConfig& cfg, bool finalized) {
    if (!curve.is_arc) {
        const geom::Vec2 u = curve.unit_tangent_at(0.0);
        return PathLimits{
            std::min({feed_mm_per_s, projected(cfg.x.max_velocity_mm_per_s, u.x_mm),
                      projected(cfg.y.max_velocity_mm_per_s, u.y_mm)}),
            std::min(projected(cfg.x.max_accel_mm_per_s2, u.x_mm), projected(cfg.y.max_accel_mm_per_s2, u.y_mm)),
            std::min(projected(cfg.x.max_jerk_mm_per_s3, u.x_mm), projected(cfg.y.max_jerk_mm_per_s3, u.y_mm))};
    }
    const double v_axis = std::min(cfg.x.max_velocity_mm_per_s, cfg.y.max_velocity_mm_per_s);
    const double a_axis = std::min(cfg.x.max_accel_mm_per_s2, cfg.y.max_accel_mm_per_s2);
    const double j_axis = std::min(cfg.x.max_jerk_mm_per_s3, cfg.y.max_jerk_mm_per_s3);
    const bool circle =
        std::fabs(curve.end_radius_mm() - curve.start_radius_mm()) <= kCircleRadiusRelDiff * curve.start_radius_mm();
    const double normal_share = circle ? kNormalShareCircle : kNormalShareSpiral;
    const double stretch = curve.max_stretch();
    const double v_centripetal = std::sqrt(normal_share * a_axis / curve.max_curvature_per_mm());
    const double normal_at_v_axis = v_axis * v_axis * curve.max_curvature_per_mm() / a_axis;  // of A
    const double tangential_share = finalized && circle && normal_at_v_axis < kNormalShareCircle
                                        ? std::sqrt(1.0 - normal_at_v_axis * normal_at_v_axis)
                                        : kTangentialShare;
    return PathLimits{std::min({feed_mm_per_s, v_axis / stretch, v_centripetal}), tangential_share * a_axis / stretch,
                      j_axis / stretch};
}

}  // namespace cnc::host::planner
