// The real recordings the replications play (protocols/audio/hydrogen-drumkits/): each copy is the file its
// README's table names, with the SHA-256 stated there; where Debian's hydrogen-drumkits is installed,
// each is the kit's sample times the stated gain (within one 16-bit step) with its first 5 ms from the
// onset at -24 dBFS, the synthetic clips' level; and every recording a protocol plays is one of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "studyapp/core/protocol_parser.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/sha256.hpp"

namespace {

const std::string kDir = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/audio/hydrogen-drumkits/";
const std::filesystem::path kKits = "/usr/share/hydrogen/data/drumkits";

struct Copy {
  std::string file, source, source_sha, copy_sha;
  double gain_db = 0.0;
};

// The rows of the README's table "| copy | source (kit/file) | source SHA-256 | gain dB | copy SHA-256 |".
std::vector<Copy> stated_copies() {
  std::ifstream in(kDir + "README.md");
  std::vector<Copy> rows;
  std::string line;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.rfind("| copy | source (kit/file)", 0) == 0) {
      in_table = true;
      continue;
    }
    if (!in_table || line.rfind("|---", 0) == 0) continue;
    if (line.empty() || line[0] != '|') break;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    for (std::string cell; std::getline(ss, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    if (cells.size() < 5) continue;
    rows.push_back({cells[0], cells[1], cells[2], cells[4], std::stod(cells[3])});
  }
  return rows;
}

// RMS in dBFS of the first 5 ms from the onset (the first sample at 1 % of the peak).
double attack_rms_dbfs(const std::vector<float>& x, double rate) {
  float peak = 0.0f;
  for (float v : x) peak = std::max(peak, std::abs(v));
  std::size_t onset = 0;
  while (onset < x.size() && std::abs(x[onset]) < 0.01f * peak) ++onset;
  const std::size_t n = std::size_t(std::lround(0.005 * rate));
  double sum = 0.0;
  for (std::size_t i = onset; i < onset + n && i < x.size(); ++i) sum += double(x[i]) * x[i];
  return 10.0 * std::log10(sum / double(n));
}

TEST(ReplicationRecordings, EachCopyHashesAsItsReadmeStates) {
  const std::vector<Copy> copies = stated_copies();
  ASSERT_EQ(copies.size(), 11u);
  for (const Copy& c : copies) {
    ASSERT_TRUE(std::filesystem::exists(kDir + c.file)) << c.file;
    EXPECT_EQ(ms::sha256_file_hex(kDir + c.file), c.copy_sha) << c.file;
    const ms::Audio a = ms::read_audio(kDir + c.file);
    EXPECT_EQ(a.sample_rate_hz, 44100.0) << c.file;
    EXPECT_EQ(a.channels, 1) << c.file;
  }
}

TEST(ReplicationRecordings, EachCopyIsTheKitsSampleTimesTheStatedGain) {
  if (!std::filesystem::exists(kKits / "The Black Pearl 1.0"))
    GTEST_SKIP() << "hydrogen-drumkits is not installed (apt-get install hydrogen-drumkits)";
  for (const Copy& c : stated_copies()) {
    const std::string source = (kKits / c.source).string();
    EXPECT_EQ(ms::sha256_file_hex(source), c.source_sha) << c.source;
    const ms::Audio original = ms::read_audio(source), copy = ms::read_audio(kDir + c.file);
    ASSERT_EQ(original.samples.size(), copy.samples.size()) << c.file;
    const double gain = std::pow(10.0, c.gain_db / 20.0), lsb = 1.0 / 32768.0;
    double worst = 0.0;
    for (std::size_t i = 0; i < copy.samples.size(); ++i)
      worst = std::max(worst, std::abs(double(copy.samples[i]) - gain * original.samples[i]));
    // One step of rounding, plus the four digits the table gives the gain in (1e-4 dB of a full scale).
    EXPECT_LE(worst, lsb + 1.2e-5) << c.file;
    EXPECT_NEAR(attack_rms_dbfs(copy.samples, copy.sample_rate_hz), -24.0, 0.05) << c.file;  // the onset may move a sample
    EXPECT_LT(c.gain_db, 0.0) << c.file;  // a quieter copy: nothing clips
  }
}

// The protocols play only recordings that are copied here (or, in the Skandalou protocol, the stand-ins
// rendered by protocols/audio/render_recordings.sh).
TEST(ReplicationRecordings, TheProtocolsPlayTheseCopies) {
  std::ifstream script(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/audio/render_recordings.sh");
  const std::string rendered((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
  std::map<std::string, int> played;
  for (const char* name : {"sterling2019", "sterling2019_handtuning", "ren2013_materials", "skandalou2017_variation"}) {
    std::vector<std::string> problems;
    const ms::Protocol p =
        ms::load_protocol(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + name + ".yaml", &problems);
    ASSERT_TRUE(problems.empty()) << name << ": " << problems.front();
    for (const ms::StimulusSource& s : p.stimuli) {
      if (s.kind != ms::StimulusKind::file) continue;
      if (s.path.rfind("audio/hydrogen-drumkits/", 0) == 0) {
        ++played[s.path.substr(std::string("audio/hydrogen-drumkits/").size())];
        continue;
      }
      // A stand-in: audio/<object>-<area>.wav, rendered from the script's <object>:<area> spec.
      ASSERT_EQ(std::string(name), "skandalou2017_variation") << s.path;
      const std::string stem = s.path.substr(6, s.path.size() - 10);
      const std::size_t dash = stem.rfind('-');
      EXPECT_NE(rendered.find(stem.substr(0, dash) + ":" + stem.substr(dash + 1) + ":"), std::string::npos) << s.path;
    }
  }
  std::vector<std::string> copied;
  for (const Copy& c : stated_copies()) copied.push_back(c.file);
  for (const auto& [file, n] : played)
    EXPECT_NE(std::find(copied.begin(), copied.end(), file), copied.end()) << file << " is played but not copied";
  EXPECT_EQ(played.count("PaisteBell-Med.wav"), 1u);
  EXPECT_EQ(played.count("PaisteRide-Med.wav"), 1u);
  EXPECT_EQ(played.count("Clave-Med.wav"), 1u);
}

}  // namespace
