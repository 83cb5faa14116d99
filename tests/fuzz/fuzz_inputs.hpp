// One input of each fuzz target: what the target feeds to its reader. Shared by the libFuzzer entry
// points (tests/fuzz/fuzz_*.cpp, built by scripts/fuzz.sh) and by the GoogleTest suite that replays
// tests/fuzz/regressions/ and the seed corpora (tests/core/test_fuzz_regressions.cpp). Each returns
// normally for an input that is accepted or refused with an InputError; any other exception, a crash,
// a hang or an unbounded allocation is a finding.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/webmushra_import.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/modes_csv.hpp"
#include "synthesis/paramset.hpp"

namespace ms::fuzz {

// A folder of this process for the files the inputs may name or become: a modes CSV a parameter set
// can refer to ("m.csv"), and the file a WAV input is written to.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("modalstudy-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::ofstream(d / "m.csv") << "freq_hz,decay_per_s,amp\n440,3,1\n880,5,0.5\n";
    return d;
  }();
  return dir;
}

template <class Fn>
void refused_cleanly(Fn fn) {
  try {
    fn();
  } catch (const InputError&) {
    // Bad input is normal input.
  }
}

// The parameter-set parser (YAML reader, every key's checks, the model's resolution).
inline void paramset(std::string_view bytes) {
  refused_cleanly([&] { (void)parse_paramset(std::string(bytes), "fuzz.yaml", scratch_dir().string()); });
}

// The protocol parser and validator, resolved against the shipped protocols/ folder so that the seeds'
// parameter sets and recordings are found. The files they name are opened (regular, within the caps)
// but not loaded: the parameter-set target covers that parser, and loading the seeds' plates would
// slow this target from thousands of inputs a second to twenty.
inline void protocol(std::string_view bytes) {
  refused_cleanly([&] {
    const std::string base = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols";
    std::vector<std::string> problems;
    const Protocol p = parse_protocol(std::string(bytes), "fuzz.yaml", base, &problems);
    ValidateOptions options;
    options.load_paramsets = false;
    (void)validate_protocol(p, options);
  });
}

// The CSV module's RFC 4180 reader, and the modes and tidy-table readers on top of it (with every
// cell of the first rows read as a number).
inline void csv(std::string_view bytes) {
  const std::string text(bytes);
  refused_cleanly([&] {
    for (const csv::Record& r : csv::parse(text, "fuzz.csv"))
      for (const std::string& cell : r.cells) (void)csv::is_number(cell);
  });
  refused_cleanly([&] { (void)parse_modes_csv(text, "fuzz.csv"); });
  refused_cleanly([&] {
    const TidyCsv t = TidyCsv::parse(text, "fuzz.csv");
    for (std::size_t r = 0; r < t.rows() && r < 64; ++r)
      for (std::size_t c = 0; c < t.header().size(); ++c) refused_cleanly([&] { (void)t.number(r, c); });
  });
}

// The audio reader (libsndfile behind the bounded reader and the WAV header check), on a file.
inline void wav(std::string_view bytes) {
  const std::string path = (scratch_dir() / "input.wav").string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
  }
  refused_cleanly([&] {
    const Audio a = read_audio(path);
    (void)mono(a);
    if (a.channels > 1) (void)mono(a, a.channels - 1);
  });
}

// The webMUSHRA config importer (its page readers, path resolution against webMUSHRA's root, the
// protocol it writes parsed and validated), on a config beside two short WAV files it may name
// (configs/audio/a.wav, configs/audio/b.wav).
inline void webmushra(std::string_view bytes) {
  static const std::filesystem::path root = [] {
    const auto r = scratch_dir() / "webmushra";
    std::filesystem::create_directories(r / "configs/audio");
    Audio a;
    a.sample_rate_hz = 44100;
    a.samples.assign(441, 0.0f);
    for (std::size_t i = 0; i < a.samples.size(); ++i) a.samples[i] = float(i % 50) / 100.0f;
    write_wav((r / "configs/audio/a.wav").string(), a, SampleFormat::pcm16);
    write_wav((r / "configs/audio/b.wav").string(), a, SampleFormat::pcm16);
    return r;
  }();
  const std::string config = (root / "configs/fuzz.yaml").string();
  {
    std::ofstream out(config, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
  }
  refused_cleanly([&] { (void)import_webmushra(config, (root / "study.yaml").string()); });
}

}  // namespace ms::fuzz
