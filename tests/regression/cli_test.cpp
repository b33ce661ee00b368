// The interface contract on bad input: exit code 2 before any work, one line
// naming the key or path, the value and what is allowed, nothing left in --out.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string bin_of(const std::string& name) { return std::string(GEOMINT_BIN_DIR) + "/" + name; }
const std::string bin = bin_of("euler_compensation");
const fs::path work = fs::path(GEOMINT_TEST_RESULTS) / ("cli-" + std::to_string(::getpid()));

struct Outcome {
  int code;
  std::string err;
};

Outcome run(const std::string& args, const std::string& binary = bin) {
  fs::create_directories(work);
  const fs::path err = work / "stderr.txt";
  const int status = std::system((binary + " " + args + " >/dev/null 2>" + err.string()).c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

// Exit 2, exactly one line on stderr containing every `needle`, and --out untouched.
void expect_rejected(const std::string& args, const std::vector<std::string>& needles,
                     const std::string& binary = bin) {
  const fs::path out = work / "out";
  fs::remove_all(out);
  const Outcome r = run("--quick --out " + out.string() + " " + args, binary);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << "missing '" << n << "' in: " << r.err;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "files left in --out for: " << args;
}

}  // namespace

TEST(Cli, NegativeStep) { expect_rejected("--set decay.h=-1", {"decay.h", "-1", "> 0"}); }
TEST(Cli, NanStep) { expect_rejected("--set decay.h=nan", {"decay.h", "nan", "finite"}); }
TEST(Cli, UnknownKey) { expect_rejected("--set nosuch.key=1", {"nosuch.key", "unknown key"}); }
TEST(Cli, StepBeyondStabilityBound) { expect_rejected("--set decay.h=2.5", {"decay.h", "2.5", "unstable for h > 2"}); }
TEST(Cli, OscillatorStepAtStabilityBound) { expect_rejected("--set oscillator.h=2", {"oscillator.h", "h >= 2"}); }
TEST(Cli, StepThatDoesNotDivideTheInterval) {
  expect_rejected("--set convergence.h=[0.3,0.1,0.05]", {"convergence.h", "divide"});
}

TEST(Cli, SceneFileWithTypeError) {
  std::ifstream in(std::string(GEOMINT_SOURCE_DIR) + "/experiments/euler_compensation/quick.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const auto at = text.find("k = 2.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 7, "k = \"two\"");
  fs::create_directories(work);
  const fs::path scene = work / "bad.toml";
  std::ofstream(scene) << text;
  const fs::path out = work / "out";
  fs::remove_all(out);
  const Outcome r = run("--scene " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("oscillator.k = \"two\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("must be a finite number > 0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, UnwritableOutputDirectory) {
  // /proc refuses new directories even to root (permission bits do not stop root).
  const Outcome r = run("--quick --out /proc/self/geomint-out");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/proc/self/geomint-out"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(Cli, UnknownOptionAndHelp) {
  EXPECT_EQ(run("--bogus").code, 2);
  const Outcome help = run("--help");
  EXPECT_EQ(help.code, 0);
}

TEST(Cli, RowlandsStepBeyondStabilityBound) {
  expect_rejected("--set h=[2.0,1.0,0.5]", {"h = [2, 1, 0.5]", "unstable for h sqrt(k/m) >= 2"},
                  bin_of("rowlands_convergence"));
}
TEST(Cli, RowlandsSingularInitialCondition) {
  expect_rejected("--set initial=[[0,0,1,0]]", {"initial", "singular"}, bin_of("rowlands_convergence"));
}
TEST(Cli, RowlandsUnknownMethod) {
  expect_rejected("--set methods=[\\\"sv\\\",\\\"leapfrog\\\"]", {"methods", "each one of"},
                  bin_of("rowlands_convergence"));
}

TEST(Cli, LobattoMeshesBeyondTheStabilityBound) {
  expect_rejected("--set meshes=[2,10,20]", {"meshes", "unstable for h omega >= sqrt(42 - 6 sqrt(29))"},
                  bin_of("lobatto_table"));
}

// measure_cloud: the modified quantities exist for even orders up to the derived one only.
TEST(Cli, MeasureCloudOddOrder) {
  expect_rejected("--set cloud.ells=[0,3]", {"cloud.ells", "even order"}, bin_of("measure_cloud"));
}
TEST(Cli, MeasureCloudUnknownDiscretization) {
  expect_rejected("--set methods=[\\\"M\\\",\\\"MM\\\"]", {"methods", "\"TT\""}, bin_of("measure_cloud"));
}
TEST(Cli, MeasureCloudUnknownPotential) {
  expect_rejected("--set potential=\\\"quartic\\\"", {"potential", "\"harmonic\" \"free\""}, bin_of("measure_cloud"));
}
TEST(Cli, MeasureCloudWindowBeyondRun) {
  expect_rejected("--set ptp_window=40", {"ptp_window", "t_end"}, bin_of("measure_cloud"));
}
