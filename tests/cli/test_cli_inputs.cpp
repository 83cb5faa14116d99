// The real command line on inputs that used to hang, blow up, escape or mislead: a FIFO or device as a
// file, a doublet split that made negative frequencies (and hung a contact render), cut-off WAVs,
// a constant signal, --channel -1, output errors at the recipe's key, and Ctrl-C during a write.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <thread>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

using ms::test::run_cli;
using ms::test::TempDir;
namespace fs = std::filesystem;

namespace {

const std::string kOneMode = "duration_s: 0.2\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n";

std::size_t temporaries(const TempDir& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir.path()))
    if (e.path().filename().string().find(".tmp") != std::string::npos) ++n;
  return n;
}

}  // namespace

TEST(CliInputs, FifoAndDeviceInputsAreRefusedAtOnce) {
  TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("m.csv").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo(dir.file("f.wav").c_str(), 0600), 0);
  const std::string set = dir.write("s.yaml", "duration_s: 0.1\nmodes: m.csv\n");
  const auto t0 = std::chrono::steady_clock::now();
  const auto fifo_csv = run_cli("synth " + set + " -o " + dir.file("o.wav"), dir);
  const auto dev = run_cli("synth /dev/zero -o " + dir.file("o.wav"), dir);
  const auto fifo_wav = run_cli("extract " + dir.file("f.wav"), dir);
  const auto fifo_prune = run_cli("prune " + dir.file("m.csv") + " --method masking", dir);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_EQ(fifo_csv.exit_code, 2);
  EXPECT_NE(fifo_csv.err.find("s.yaml:2:8: modes: cannot use"), std::string::npos) << fifo_csv.err;
  EXPECT_NE(fifo_csv.err.find("is a FIFO"), std::string::npos) << fifo_csv.err;
  EXPECT_EQ(dev.exit_code, 2);
  EXPECT_NE(dev.err.find("/dev/zero: is a device"), std::string::npos) << dev.err;
  EXPECT_EQ(fifo_wav.exit_code, 2);
  EXPECT_NE(fifo_wav.err.find("f.wav: is a FIFO"), std::string::npos) << fifo_wav.err;
  EXPECT_EQ(fifo_prune.exit_code, 2);
  EXPECT_NE(fifo_prune.err.find("m.csv: is a FIFO"), std::string::npos) << fifo_prune.err;
  EXPECT_FALSE(fs::exists(dir.file("o.wav")));
}

TEST(CliInputs, ModesCsvOutsideTheSetNeedsAllowOutside) {
  TempDir dir;
  dir.write("outside/m.csv", "freq_hz,decay_per_s,amp\n440,3,1\n");
  const std::string set = dir.write("sets/s.yaml", "duration_s: 0.1\nmodes: ../outside/m.csv\n");
  const auto refused = run_cli("synth " + set + " -o " + dir.file("o.wav"), dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("s.yaml:2:8: modes: path '../outside/m.csv' is outside the parameter set's folder"),
            std::string::npos) << refused.err;
  const auto allowed = run_cli("synth " + set + " -o " + dir.file("o.wav") + " --allow-outside", dir);
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
}

TEST(CliInputs, DoubletSplitsAreRangeCheckedAndContactRendersStayBounded) {
  TempDir dir;
  const std::string set = dir.write("s.yaml", kOneMode + "excitation: {type: hertz, contact_s: 0.05}\n");
  const auto t0 = std::chrono::steady_clock::now();
  const auto big = run_cli("synth " + set + " -o " + dir.file("o.wav") + " --set effects.doublets.split_rel=100000", dir);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_NE(big.err.find("--set effects.doublets.split_rel: effects.doublets.split_rel: must lie in (0, 1)"),
            std::string::npos) << big.err;
  const auto neg = run_cli("synth " + set + " -o " + dir.file("o.wav") + " --modes-out " + dir.file("m.csv") +
                               " --set effects.doublets.split_hz=1000", dir);
  EXPECT_EQ(neg.exit_code, 2);
  EXPECT_NE(neg.err.find("must be less than the frequency of every mode it splits (the lowest is 440"),
            std::string::npos) << neg.err;
  EXPECT_FALSE(fs::exists(dir.file("m.csv")));
}

TEST(CliInputs, CutOffWavsConstantSignalsAndNegativeChannelsAreNamedPrecisely) {
  TempDir dir;
  std::vector<float> x(22050);
  for (std::size_t n = 0; n < x.size(); ++n) x[n] = float(0.5 * std::exp(-8.0 * n / 44100) * std::sin(2 * std::numbers::pi * 440 * n / 44100));
  ms::write_wav(dir.file("full.wav"), ms::Audio{44100, 1, x}, ms::SampleFormat::pcm16);
  const std::string full = [&] {
    std::ifstream in(dir.file("full.wav"), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }();
  dir.write("half.wav", full.substr(0, full.size() / 2));
  const auto half = run_cli("extract " + dir.file("half.wav"), dir);
  EXPECT_EQ(half.exit_code, 2);
  EXPECT_NE(half.err.find("half.wav: truncated: the WAV header declares 44100 bytes of samples"), std::string::npos)
      << half.err;
  ms::write_wav(dir.file("dc.wav"), ms::Audio{44100, 1, std::vector<float>(44100, 0.001f)}, ms::SampleFormat::float32);
  const auto dc = run_cli("extract " + dir.file("dc.wav"), dir);
  EXPECT_EQ(dc.exit_code, 2);
  EXPECT_NE(dc.err.find("dc.wav: constant: every sample is 0.001 (no impact in it)"), std::string::npos) << dc.err;
  EXPECT_EQ(dc.err.find("clipped"), std::string::npos) << dc.err;
  const auto channel = run_cli("extract " + dir.file("full.wav") + " --channel -1", dir);
  EXPECT_NE(channel.exit_code, 0);
  EXPECT_NE(channel.err.find("--channel: must be 0 or more"), std::string::npos) << channel.err;
}

TEST(CliInputs, OutputStageErrorsNameTheRecipesKey) {
  TempDir dir;
  const std::string set =
      dir.write("s.yaml", "duration_s: 0.1\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 4}]\n"
                          "level: {normalize: none}\noutput: {format: pcm16}\n");
  const auto r = run_cli("synth " + set + " -o " + dir.file("o.wav"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("s.yaml:4:18: output.format: pcm16 cannot hold the rendered peak of +12.0 dBFS"),
            std::string::npos) << r.err;
  const auto f = run_cli("synth " + set + " -o " + dir.file("o.wav") + " --format pcm24", dir);
  EXPECT_NE(f.err.find("modalstudy: --format: output.format: pcm24 cannot hold"), std::string::npos) << f.err;
  EXPECT_FALSE(fs::exists(dir.file("o.wav")));
}

TEST(CliInputs, AnInterruptedSynthLeavesNoTemporaryFile) {
  TempDir dir;
  // 600 s at 96 kHz: a 230 MB float WAV, written long enough to be interrupted while it is.
  const std::string set = dir.write("long.yaml", "sample_rate: 96000\nduration_s: 600\n"
                                                 "modes: [{freq_hz: 440, decay_per_s: 0.01, amp: 0.5}]\n"
                                                 "level: {normalize: none}\n");
  const std::string out = dir.file("out.wav");
  for (int sig : {SIGINT, SIGTERM}) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::signal(SIGINT, SIG_DFL);  // as from a terminal, whatever this test runner ignores
      ::signal(SIGTERM, SIG_DFL);
      ::execl(MODALSTUDY_BIN, MODALSTUDY_BIN, "synth", set.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Interrupt once the temporary file exists and has grown.
    bool seen = false;
    for (int i = 0; i < 120000 && !seen; ++i) {
      for (const auto& e : fs::directory_iterator(dir.path()))
        if (e.path().filename().string().rfind(".out.wav.tmp", 0) == 0 && fs::file_size(e.path()) > 0) seen = true;
      if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(seen) << "the temporary file never appeared";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_EQ(temporaries(dir), 0u);
    EXPECT_FALSE(fs::exists(out));
  }
}
