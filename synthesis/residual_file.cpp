// Residual file codec; see residual_file.hpp.
#include "synthesis/residual_file.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "synthesis/atomic_file.hpp"
#include "synthesis/exact_number.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace {

constexpr const char* kFormat = "modalstudy-residual 1";
constexpr const char* kPayload = "float32-le";
constexpr const char* kHeaderEnd = "\n...\n";
constexpr std::size_t kMaxFftSize = 65536;

std::uint32_t little_endian(std::uint32_t v) {
  if constexpr (std::endian::native == std::endian::big)
    v = ((v & 0xffu) << 24) | ((v & 0xff00u) << 8) | ((v >> 8) & 0xff00u) | (v >> 24);
  return v;
}

// The problem with `r` as a whole, "" when it is a valid residual (values are checked separately).
std::string shape_problem(const ResidualSpectrogram& r) {
  if (!(r.sample_rate_hz > 0.0) || !std::isfinite(r.sample_rate_hz)) return "sample rate must be positive";
  if (r.grid.fft_size < 16 || r.grid.fft_size > kMaxFftSize || r.grid.fft_size % 2 != 0)
    return "stft.fft_size must be even, 16 .. " + std::to_string(kMaxFftSize);
  if (r.grid.hop < 1 || r.grid.hop > r.grid.fft_size / 2) return "stft.hop must lie in 1 .. fft_size / 2";
  if (r.frames < 1) return "a residual has at least one frame";
  if (r.power.size() != r.frames * r.grid.bins()) return "power holds frames x bins values";
  if (r.modes.empty()) return "a residual needs the source object's modes (at least one)";
  if (r.source.find_first_of("\r\n") != std::string::npos) return "source must be one line";
  for (const Mode& m : r.modes)
    if (!(m.freq_hz > 0.0 && m.freq_hz < 0.5 * r.sample_rate_hz) || !(m.decay_per_s >= 0.0) ||
        !std::isfinite(m.decay_per_s) || !(m.amp >= 0.0) || !std::isfinite(m.amp) || !std::isfinite(m.phase_rad))
      return "every mode needs 0 < freq_hz < Nyquist and finite decay_per_s, amp >= 0 and phase_rad";
  return "";
}

std::size_t count(const YamlReader& r, const YAML::Node& map, const std::string& path, const char* key,
                  long long lo, long long hi) {
  const std::string key_path = path.empty() ? key : path + "." + key;
  if (!map[key]) r.fail(map, path, std::string("missing '") + key + "'");
  const long long v = r.integer(map[key], key_path);
  if (v < lo || v > hi)
    r.fail(map[key], key_path, "must lie in " + std::to_string(lo) + " .. " + std::to_string(hi));
  return std::size_t(v);
}

std::string required_text(const YamlReader& r, const YAML::Node& map, const std::string& path, const char* key) {
  const std::string key_path = path.empty() ? key : path + "." + key;
  if (!map[key]) r.fail(map, path, std::string("missing '") + key + "'");
  return r.text(map[key], key_path);
}

std::vector<Mode> read_modes(const YamlReader& r, const YAML::Node& node, double sample_rate_hz) {
  if (!node.IsMap()) r.fail(node, "modes", "expected {freq_hz: [...], decay_per_s: [...], amp: [...], phase_rad: [...]}");
  r.check_keys(node, "modes", {"freq_hz", "decay_per_s", "amp", "phase_rad"});
  std::array<std::vector<double>, 4> columns;
  const std::array<const char*, 4> keys = {"freq_hz", "decay_per_s", "amp", "phase_rad"};
  for (std::size_t c = 0; c < keys.size(); ++c) {
    if (!node[keys[c]]) r.fail(node, "modes", std::string("missing '") + keys[c] + "'");
    columns[c] = r.numbers(node[keys[c]], std::string("modes.") + keys[c]);
    if (columns[c].size() != columns[0].size())
      r.fail(node[keys[c]], std::string("modes.") + keys[c],
             "holds " + std::to_string(columns[c].size()) + " values, modes.freq_hz " + std::to_string(columns[0].size()));
  }
  if (columns[0].empty()) r.fail(node["freq_hz"], "modes.freq_hz", "a residual needs at least one source mode");
  std::vector<Mode> modes(columns[0].size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    modes[i] = Mode{columns[0][i], columns[1][i], columns[2][i], columns[3][i]};
    if (!(modes[i].freq_hz > 0.0 && modes[i].freq_hz < 0.5 * sample_rate_hz))
      r.fail(node["freq_hz"][i], "modes.freq_hz" + at, "must lie between 0 and Nyquist (" + exact_number(0.5 * sample_rate_hz) + " Hz)");
    if (modes[i].decay_per_s < 0.0) r.fail(node["decay_per_s"][i], "modes.decay_per_s" + at, "must be >= 0");
    if (modes[i].amp < 0.0) r.fail(node["amp"][i], "modes.amp" + at, "must be >= 0");
  }
  return modes;
}

}  // namespace

ResidualSpectrogram parse_residual_file(const std::string& bytes, const std::string& file) {
  const std::size_t end = bytes.find(kHeaderEnd);
  if (end == std::string::npos)
    throw InputError(SourceLocation{file, 1, 1}, "not a residual file: no line '...' ends a YAML header");
  const YamlReader r(file);
  const YAML::Node root = r.load(bytes.substr(0, end + 1));
  if (!root.IsMap()) throw InputError(SourceLocation{file, 1, 1}, "not a residual file: the header is not a map of keys");
  if (!root["format"] || r.text(root["format"], "format") != kFormat)
    r.fail(root["format"] ? root["format"] : root, "format",
           std::string("not a residual file (expected 'format: ") + kFormat + "')");
  r.check_keys(root, "", {"format", "source", "sample_rate_hz", "stft", "bins", "frames", "power", "modes"});
  ResidualSpectrogram out;
  if (root["source"]) {
    out.source = r.text(root["source"], "source");
    if (out.source.find_first_of("\r\n") != std::string::npos) r.fail(root["source"], "source", "must be one line");
  }
  if (!root["sample_rate_hz"]) r.fail(root, "", "missing 'sample_rate_hz'");
  out.sample_rate_hz = r.positive(root["sample_rate_hz"], "sample_rate_hz");
  if (!root["stft"]) r.fail(root, "", "missing 'stft'");
  const YAML::Node stft = root["stft"];
  r.check_keys(stft, "stft", {"window", "fft_size", "hop"});
  if (required_text(r, stft, "stft", "window") != "hann")
    r.fail(stft["window"], "stft.window", "only 'hann' (periodic) is known");
  out.grid.fft_size = count(r, stft, "stft", "fft_size", 16, kMaxFftSize);
  if (out.grid.fft_size % 2 != 0) r.fail(stft["fft_size"], "stft.fft_size", "must be even");
  out.grid.hop = count(r, stft, "stft", "hop", 1, (long long)out.grid.fft_size / 2);
  if (count(r, root, "", "bins", 1, kMaxFftSize) != out.grid.bins())
    r.fail(root["bins"], "bins", "must be stft.fft_size / 2 + 1 = " + std::to_string(out.grid.bins()));
  out.frames = count(r, root, "", "frames", 1, (long long)(kResidualFileLimit.max_bytes / 4 / out.grid.bins()));
  if (required_text(r, root, "", "power") != kPayload)
    r.fail(root["power"], "power", std::string("only '") + kPayload + "' is known");
  if (!root["modes"]) r.fail(root, "", "missing 'modes'");
  out.modes = read_modes(r, root["modes"], out.sample_rate_hz);

  const std::size_t bins = out.grid.bins(), values = out.frames * bins, offset = end + std::strlen(kHeaderEnd);
  const std::size_t held = bytes.size() - offset;
  if (held != values * 4)
    throw InputError(SourceLocation{file, 0, 0},
                     "payload: " + std::to_string(held) + " bytes after the header, but frames x bins = " +
                         std::to_string(out.frames) + " x " + std::to_string(bins) + " float32 need " +
                         std::to_string(values * 4) + (held < values * 4 ? " (cut off?)" : ""));
  out.power.resize(values);
  for (std::size_t i = 0; i < values; ++i) {
    std::uint32_t word = 0;
    std::memcpy(&word, bytes.data() + offset + 4 * i, 4);
    const float v = std::bit_cast<float>(little_endian(word));
    if (!std::isfinite(v) || v < 0.0f)
      throw InputError(SourceLocation{file, 0, 0},
                       "payload: frame " + std::to_string(i / bins) + ", bin " + std::to_string(i % bins) +
                           " (byte " + std::to_string(offset + 4 * i) + ") holds " + exact_number(v) +
                           ", not a power (finite, >= 0)");
    out.power[i] = v;
  }
  return out;
}

ResidualSpectrogram read_residual_file(const std::string& path) {
  return parse_residual_file(read_bounded_file(path, kResidualFileLimit), path);
}

std::string residual_file_bytes(const ResidualSpectrogram& r) {
  if (const std::string problem = shape_problem(r); !problem.empty())
    throw std::invalid_argument("residual: " + problem);
  for (float v : r.power)
    if (!std::isfinite(v) || v < 0.0f) throw std::invalid_argument("residual: a power is negative or not finite");
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormat;
  if (!r.source.empty()) out << YAML::Key << "source" << YAML::Value << r.source;
  out << YAML::Key << "sample_rate_hz" << YAML::Value << exact_number(r.sample_rate_hz);
  out << YAML::Key << "stft" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "window"
      << YAML::Value << "hann" << YAML::Key << "fft_size" << YAML::Value << r.grid.fft_size << YAML::Key
      << "hop" << YAML::Value << r.grid.hop << YAML::EndMap;
  out << YAML::Key << "bins" << YAML::Value << r.grid.bins();
  out << YAML::Key << "frames" << YAML::Value << r.frames;
  out << YAML::Key << "power" << YAML::Value << kPayload;
  out << YAML::Key << "modes" << YAML::Value << YAML::BeginMap;
  const auto column = [&](const char* key, double Mode::*field) {
    out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const Mode& m : r.modes) out << exact_number(m.*field);
    out << YAML::EndSeq;
  };
  column("freq_hz", &Mode::freq_hz);
  column("decay_per_s", &Mode::decay_per_s);
  column("amp", &Mode::amp);
  column("phase_rad", &Mode::phase_rad);
  out << YAML::EndMap << YAML::EndMap;
  std::string bytes = std::string(out.c_str()) + kHeaderEnd;
  const std::size_t offset = bytes.size();
  bytes.resize(offset + 4 * r.power.size());
  for (std::size_t i = 0; i < r.power.size(); ++i) {
    const std::uint32_t word = little_endian(std::bit_cast<std::uint32_t>(r.power[i]));
    std::memcpy(bytes.data() + offset + 4 * i, &word, 4);
  }
  return bytes;
}

void write_residual_file(const std::string& path, const ResidualSpectrogram& r) {
  write_file_atomically(path, residual_file_bytes(r));
}

}  // namespace ms
