#include "synthesis/stimulus_build.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include "synthesis/atomic_file.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/sha256.hpp"
#include "synthesis/stimulus.hpp"

namespace ms {

namespace fs = std::filesystem;

namespace {

struct Job {
  std::string source, name;
};

std::vector<Job> collect(const std::vector<std::string>& inputs) {
  std::vector<Job> jobs;
  for (const auto& input : inputs) {
    const fs::path in(input);
    std::error_code status_error;
    const fs::file_status status = fs::status(in, status_error);
    if (status_error && status_error != std::errc::no_such_file_or_directory)
      throw InputError(SourceLocation{input, 0, 0}, "cannot read: " + status_error.message());
    if (!fs::exists(status)) throw InputError(SourceLocation{input, 0, 0}, "no such file or folder");
    if (fs::is_directory(status)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::recursive_directory_iterator(in))
        if (e.is_regular_file() && (e.path().extension() == ".yaml" || e.path().extension() == ".yml"))
          files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        fs::path rel = fs::relative(f, in);
        rel.replace_extension(".wav");
        jobs.push_back({f.string(), rel.generic_string()});
      }
    } else {
      jobs.push_back({in.string(), in.stem().string() + ".wav"});
    }
  }
  std::map<std::string, std::string> seen;
  for (const auto& j : jobs) {
    auto [it, fresh] = seen.emplace(j.name, j.source);
    if (!fresh)
      throw InputError(SourceLocation{j.source, 0, 0},
                       "renders to the same output '" + j.name + "' as " + it->second);
  }
  return jobs;
}

std::map<std::string, nlohmann::json> read_manifest(const fs::path& path) {
  std::map<std::string, nlohmann::json> by_name;
  std::error_code ec;
  if (!fs::exists(path, ec)) return by_name;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_bounded_file(path.string(), kJsonFileLimit));
    for (const auto& e : j.at("stimuli")) by_name[e.at("name").get<std::string>()] = e;
  } catch (const std::exception&) {
    by_name.clear();  // a damaged manifest only costs a full re-render
  }
  return by_name;
}

// Runs fn(i) for i in [0, count) on `threads` threads (work stealing by an atomic counter).
template <class Fn>
void parallel_for(std::size_t count, unsigned threads, Fn fn) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t k; (k = next++) < count;) fn(k);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

}  // namespace

BuildReport build_stimuli(const std::vector<std::string>& inputs, const std::string& out_dir,
                          unsigned threads, std::vector<std::string>* errors) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Job> jobs = collect(inputs);
  if (jobs.empty()) throw InputError(SourceLocation{inputs.empty() ? "" : inputs[0], 0, 0},
                                     "no parameter sets (*.yaml) found");
  // Read and check every set before writing anything.
  std::vector<ParamSet> sets(jobs.size());
  std::vector<std::string> problem_of(jobs.size());
  parallel_for(jobs.size(), std::max(1u, threads), [&](std::size_t i) {
    try {
      sets[i] = load_paramset(jobs[i].source);
    } catch (const InputError& e) {
      problem_of[i] = e.what();
    }
  });
  std::vector<std::string> problems;
  for (const auto& pr : problem_of)
    if (!pr.empty()) problems.push_back(pr);
  if (!problems.empty()) {
    if (errors) *errors = problems;
    throw InputError(problems.front() + (problems.size() > 1 ? " (and " + std::to_string(problems.size() - 1) +
                                                                   " more)" : ""));
  }
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir, ec))
    throw InputError(SourceLocation{out_dir, 0, 0}, "cannot create output folder");
  const fs::path manifest_path = fs::path(out_dir) / "manifest.json";
  const auto previous = read_manifest(manifest_path);

  BuildReport report;
  report.entries.resize(jobs.size());
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    BuildEntry& e = report.entries[i];
    e.name = jobs[i].name;
    e.source = jobs[i].source;
    e.recipe_hash = sets[i].recipe_hash;
    const fs::path out = fs::path(out_dir) / e.name;
    auto it = previous.find(e.name);
    if (it != previous.end() && it->second.value("recipe_hash", "") == e.recipe_hash && fs::exists(out, ec) &&
        sha256_file_hex(out.string()) == it->second.value("sha256", "")) {
      e.sha256 = it->second.value("sha256", "");
      e.frames = it->second.value("frames", std::size_t(0));
      e.sample_rate_hz = it->second.value("sample_rate", 0.0);
      e.modes = it->second.value("modes", std::size_t(0));
      e.warnings = it->second.value("warnings", std::vector<std::string>{});
      ++report.reused;
    } else {
      todo.push_back(i);
    }
  }

  report.threads = std::max(1u, std::min<unsigned>(threads, unsigned(std::max<std::size_t>(todo.size(), 1))));
  std::mutex failure_mutex;
  std::vector<std::string> failures;
  parallel_for(todo.size(), report.threads, [&](std::size_t k) {
    const std::size_t i = todo[k];
    BuildEntry& e = report.entries[i];
    try {
      const RenderedStimulus r = render_stimulus(sets[i]);
      const fs::path out = fs::path(out_dir) / e.name;
      fs::create_directories(out.parent_path());
      check_writable(sets[i], r.audio, sets[i].format_where);
      write_wav(out.string(), r.audio, sets[i].format);
      e.sha256 = sha256_file_hex(out.string());
      e.frames = r.audio.frames();
      e.sample_rate_hz = r.audio.sample_rate_hz;
      e.modes = r.modes_rendered;
      e.warnings = r.warnings;
      e.rendered = true;
    } catch (const std::exception& ex) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      failures.push_back(ex.what());
    }
  });
  report.rendered = todo.size() - failures.size();

  // The manifest lists only what exists and is verified, so it is never stale.
  nlohmann::json manifest = {{"version", 1}, {"stimuli", nlohmann::json::array()}};
  for (const auto& e : report.entries) {
    if (e.sha256.empty()) continue;
    manifest["stimuli"].push_back({{"name", e.name},          {"source", e.source},
                                   {"recipe_hash", e.recipe_hash}, {"sha256", e.sha256},
                                   {"frames", e.frames},      {"sample_rate", e.sample_rate_hz},
                                   {"modes", e.modes},        {"warnings", e.warnings}});
  }
  write_file_atomically(manifest_path.string(), manifest.dump(2) + "\n");
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!failures.empty()) {
    if (errors) *errors = failures;
    throw InputError(failures.front());
  }
  return report;
}

}  // namespace ms
