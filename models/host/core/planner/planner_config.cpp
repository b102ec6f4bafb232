#include "host/core/planner/planner_config.hpp"

#include <cmath>

#include "common/bad_input.hpp"

namespace cnc::host::planner {

namespace {

void require_positive(double value, const std::string& field, const std::string& where) {
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw BadInput(where, field + " must be a finite value > 0 (got " + std::to_string(value) + ")");
    }
}

void require_non_negative(double value, const std::string& field, const std::string& where) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
        throw BadInput(where, field + " must be a finite value >= 0 (got " + std::to_string(value) + ")");
    }
}

void validate_axis(const AxisLimits& axis, const std::string& name, const std::string& where) {
    require_positive(axis.max_velocity_mm_per_s, name + ".max_velocity_mm_per_s", where);
    require_positive(axis.max_accel_mm_per_s2, name + ".max_accel_mm_per_s2", where);
    require_positive(axis.max_jerk_mm_per_s3, name + ".max_jerk_mm_per_s3", where);
}

}  // namespace

void validate(const PlannerConfig& cfg, const std::string& where) {
    validate_axis(cfg.x, "x", where);
    validate_axis(cfg.y, "y", where);
    require_non_negative(cfg.path_tolerance_mm, "path_tolerance_mm", where);
    if (cfg.lookahead_moves < 1) {
        throw BadInput(where, "lookahead_moves must be >= 1 (got " + std::to_string(cfg.lookahead_moves) + ")");
    }
}

}  // namespace cnc::host::planner
