// Rendering a folder of parameter sets, incrementally: OUTDIR/manifest.json records each output's
// SHA-256 and recipe hash, and a re-run renders only what changed. All sets are read and checked
// before anything is written; every WAV and the manifest are written atomically.
#pragma once
#include <string>
#include <vector>

namespace ms {

struct BuildEntry {
  std::string name;         // output path relative to OUTDIR, e.g. "bar/steel.wav"
  std::string source;       // parameter set path
  std::string recipe_hash;
  std::string sha256;       // of the WAV file
  std::size_t frames = 0;
  double sample_rate_hz = 0;
  std::size_t modes = 0;
  bool rendered = false;    // false: up to date, reused
  std::vector<std::string> warnings;
};

struct BuildReport {
  std::vector<BuildEntry> entries;
  std::size_t rendered = 0, reused = 0;
  unsigned threads = 1;
  double seconds = 0;
};

// Inputs are parameter-set files or folders (searched recursively for *.yaml / *.yml).
// Throws InputError (first problem; all problems are listed in the message lines of `errors`).
BuildReport build_stimuli(const std::vector<std::string>& inputs, const std::string& out_dir,
                          unsigned threads, std::vector<std::string>* errors = nullptr);

}  // namespace ms
