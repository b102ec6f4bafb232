#include "sweep/sweep_slurm.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace cnc::sim {

std::size_t task_count(std::size_t points, std::size_t per_task) {
    return (points + per_task - 1) / per_task;
}

std::size_t default_points_per_task(std::size_t points) {
    return std::max<std::size_t>(1, task_count(points, kSlurmMaxTasks));
}

std::pair<std::size_t, std::size_t> task_points(std::size_t task, std::size_t points, std::size_t per_task) {
    return {std::min(points, task * per_task), std::min(points, (task + 1) * per_task)};
}

std::string array_list(const std::vector<std::size_t>& tasks) {
    std::string out;
    for (std::size_t i = 0; i < tasks.size();) {
        std::size_t j = i;
        while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
        out += (out.empty() ? "" : ",") + std::to_string(tasks[i]);
        if (j > i) out += "-" + std::to_string(tasks[j]);
        i = j + 1;
    }
    return out;
}

nlohmann::json submission_json(const SlurmSubmission& s) {
    return {{"sweep", s.sweep_file},         {"out", s.out_dir},         {"cwd", s.cwd},   {"cncsim", s.self_exe},
            {"points_per_task", s.per_task}, {"partition", s.partition}, {"time", s.time}, {"points", s.point_sets}};
}

std::optional<SlurmSubmission> parse_submission(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return std::nullopt;
    for (const char* key : {"sweep", "out", "cwd", "cncsim", "partition", "time"}) {
        if (!j.contains(key) || !j.at(key).is_string()) return std::nullopt;
    }
    if (!j.contains("points_per_task") || !j.at("points_per_task").is_number_unsigned() ||
        j.at("points_per_task").get<std::size_t>() == 0 || !j.contains("points") || !j.at("points").is_array())
        return std::nullopt;
    SlurmSubmission s{j.at("sweep"),           j.at("out"),       j.at("cwd"),  j.at("cncsim"),
                      j.at("points_per_task"), j.at("partition"), j.at("time"), {}};
    for (const nlohmann::json& point : j.at("points")) {
        if (!point.is_array() || !std::all_of(point.begin(), point.end(), [](const auto& v) { return v.is_string(); }))
            return std::nullopt;
        s.point_sets.push_back(point.get<std::vector<std::string>>());
    }
    return s;
}

std::string shell_word(const std::string& word) {
    const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
               std::string("/._-+=:,@%").find(c) != std::string::npos;
    });
    if (plain) return word;
    std::string out = "'";
    for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string job_script(const SlurmSubmission& s, const std::string& log_pattern) {
    std::string out = "#!/bin/sh\n#SBATCH --job-name=cncsim-sweep\n#SBATCH --output=" + log_pattern + "\n";
    if (!s.partition.empty()) out += "#SBATCH --partition=" + s.partition + "\n";
    if (!s.time.empty()) out += "#SBATCH --time=" + s.time + "\n";
    // The task's points run one at a time: the task is given one CPU.
    out += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
    out += "# A task of `cncsim sweep " + s.sweep_file + " --out " + s.out_dir +
           " --slurm`: its points, as the local sweep runs them (docs/sweeps.md).\n";
    out += "cd " + shell_word(s.cwd) + " || exit 2\n";
    out += fmt::format(FMT_STRING("exec {} sweep {} --out {} --point \"$SLURM_ARRAY_TASK_ID\" --points-per-task {}\n"),
                       shell_word(s.self_exe), shell_word(s.sweep_file), shell_word(s.out_dir), s.per_task);
    return out;
}

}  // namespace cnc::sim
