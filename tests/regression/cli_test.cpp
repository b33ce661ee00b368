// The interface contract on bad input: exit code 2 before any work, one line
// naming the key or path, the value and what is allowed, nothing left in --out.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "summary.hpp"

namespace fs = std::filesystem;

namespace cli_test {  // the file's scope (the tests build as one translation unit)

namespace {

std::string bin_of(const std::string& name) { return std::string(GEOMINT_BIN_DIR) + "/" + name; }
const std::string bin = bin_of("euler_compensation");
const fs::path work = fs::path(GEOMINT_TEST_RESULTS) / ("cli-" + std::to_string(::getpid()));
// The test process removes its working directory when it ends (destroyed before `work`).
const struct RemoveWork {
  ~RemoveWork() {
    std::error_code ec;
    fs::remove_all(work, ec);
  }
} remove_work;

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
  EXPECT_RUN_REFUSED(fs::path(binary).filename().string() + " " + args, r.code, r.err, 2, needles);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "files left in --out for: " << args;
}

}  // namespace

TEST(Cli, NegativeStep) { expect_rejected("--set decay.h=-1", {"decay.h", "-1", "> 0"}); }
TEST(Cli, NanStep) { expect_rejected("--set decay.h=nan", {"decay.h", "nan", "finite"}); }
TEST(Cli, RefusesARunPlannedBeyondMaxSeconds) {  // (the quick scene's plan: seconds)
  expect_rejected("--max-seconds 0.001", {"the plan estimates", "over --max-seconds 0.001"});
}
TEST(Cli, UnknownKey) { expect_rejected("--set nosuch.key=1", {"nosuch.key", "unknown key"}); }
TEST(Cli, StepBeyondStabilityBound) { expect_rejected("--set decay.h=2.5", {"decay.h", "2.5", "unstable for h > 2"}); }
TEST(Cli, OscillatorStepAtStabilityBound) { expect_rejected("--set oscillator.h=2", {"oscillator.h", "symplectic_euler_pq is unstable for h omega >= 2"}); }
TEST(Cli, StepThatDoesNotDivideTheInterval) {
  expect_rejected("--set convergence.h=[0.3,0.1,0.05]", {"convergence.h", "divide"});
}

TEST(Cli, SceneFileWithTypeError) {
  // An overlay of the paper scene with one wrong value: the key, the value and its file are named.
  fs::create_directories(work);
  const fs::path scene = work / "bad.toml";
  std::ofstream(scene) << "base = \"" << GEOMINT_SOURCE_DIR << "/experiments/euler_compensation/euler_compensation.toml\"\n"
                       << "[oscillator]\nk = \"two\"\n";
  const fs::path out = work / "out";
  fs::remove_all(out);
  const Outcome r = run("--scene " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("oscillator.k = \"two\" (in " + scene.string() + ")"), std::string::npos) << r.err;
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

TEST(Cli, OutputDirectoryThatIsNotAResultsDirectoryIsNeverReplaced) {
  // --out naming a directory of a user's files (as --out ~ would): refused before any work, untouched.
  const fs::path home = work / "home";
  fs::create_directories(home);
  std::ofstream(home / "precious.txt") << "x";
  const Outcome r = run("--quick --out " + home.string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("not a results directory"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(home), fs::directory_iterator{}), 1);
  EXPECT_FALSE(fs::exists(work / "home.partial"));
}

TEST(Cli, PlanValidatesAndRunsNothing) {
  // --plan: exit 0 with a line per study, no output directory; a bad scene is still refused (exit 2).
  const fs::path out = work / "plan-out", listing = work / "plan.txt";
  fs::create_directories(work);
  fs::remove_all(out);
  const int status = std::system((bin + " --quick --plan --out " + out.string() + " >" + listing.string() + " 2>/dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::ifstream in(listing);
  std::stringstream ss;
  ss << in.rdbuf();
  for (const char* study : {"decay", "gompertz", "oscillator", "convergence", "cost"})
    EXPECT_NE(ss.str().find(study), std::string::npos) << ss.str();
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(work / "plan-out.partial"));
  EXPECT_EQ(run("--quick --plan --set decay.h=-1").code, 2);
}

TEST(Cli, ScenesAreFoundWhereGeomintExperimentsPoints) {
  // A build moved away from its sources reads the scenes of GEOMINT_EXPERIMENTS/<name>: here a copy
  // whose quick scene has an unknown key, so the refusal names the copy.
  const fs::path exps = work / "experiments", copy = exps / "euler_compensation";
  fs::remove_all(exps);
  fs::create_directories(exps);
  fs::copy(fs::path(GEOMINT_SOURCE_DIR) / "experiments" / "euler_compensation", copy, fs::copy_options::recursive);
  std::ofstream(copy / "quick.toml", std::ios::app) << "\n[nosuch]\nkey = 1\n";
  const Outcome r = run("--quick --plan");  // the sources' own quick scene: valid
  EXPECT_EQ(r.code, 0) << r.err;
  const Outcome moved = run("--quick --plan", "GEOMINT_EXPERIMENTS=" + exps.string() + " " + bin);
  EXPECT_EQ(moved.code, 2) << moved.err;
  EXPECT_NE(moved.err.find(copy.string()), std::string::npos) << moved.err;
  EXPECT_NE(moved.err.find("nosuch.key"), std::string::npos) << moved.err;
}

TEST(Cli, UnknownOptionAndHelp) {
  EXPECT_EQ(run("--bogus").code, 2);
  const Outcome help = run("--help");
  EXPECT_EQ(help.code, 0);
}

TEST(Cli, RowlandsStepBeyondStabilityBound) {
  expect_rejected("--set h=[2.0,1.0,0.5]", {"h = [2, 1, 0.5]", "stormer_verlet is unstable for h omega >= 2", "h = 2, omega = sqrt(k/m)"},
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
  expect_rejected("--set potential=\\\"quartic\\\"", {"potential", "\"harmonic\", \"free\""}, bin_of("measure_cloud"));
}
TEST(Cli, MeasureCloudWindowBeyondRun) {
  expect_rejected("--set ptp_window=40", {"ptp_window", "t_end"}, bin_of("measure_cloud"));
}

// Studies: the scene says what runs; --study narrows it; a study that does not
// exist, or a scene that asks for none, is bad input.
TEST(Cli, UnknownStudyNamesTheValidOnes) {
  expect_rejected("--study nosuch", {"--study nosuch", "no such study", "decay, gompertz, oscillator, convergence, cost"});
}
TEST(Cli, SceneAskingForNoStudy) {
  expect_rejected("--set studies=[]", {"asks for no study", "decay, gompertz"});
}
TEST(Cli, StudyTheSceneDoesNotAskFor) {
  expect_rejected("--set studies=[\\\"decay\\\"] --study gompertz", {"--study gompertz", "does not ask for it", "decay"});
}
TEST(Cli, AStudyValidatesOnlyItsOwnKeys) {
  // A step beyond the bound in another study's section is not looked at when that study does not run ...
  const fs::path out = work / "only-decay";
  fs::remove_all(out);
  const Outcome r = run("--quick --study decay --set gompertz.h=99 --out " + out.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "fig2_decay.csv"));
  EXPECT_FALSE(fs::exists(out / "fig3_gompertz.csv"));
  // ... and is refused when it does.
  expect_rejected("--study gompertz --set gompertz.h=99", {"gompertz.h", "unstable"});
}
TEST(Cli, MissingKeyIsNamedWithTheStudyThatNeedsIt) {
  fs::create_directories(work);
  const fs::path scene = work / "partial.toml";
  std::ofstream(scene) << "[decay]\nalpha = 1.0\ny0 = 1.0\nh = 0.3\n";
  const fs::path out = work / "out";
  fs::remove_all(out);
  const Outcome r = run("--scene " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing key 'decay.steps' (an integer), needed by study decay"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}
TEST(Cli, ListStudiesAndHelp) {
  const fs::path listing = work / "studies.txt";
  fs::create_directories(work);
  ASSERT_EQ(std::system((bin + " --list-studies > " + listing.string()).c_str()), 0);
  std::ifstream in(listing);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find("convergence\t000 Fig. 9: error in H against h: orders 1 and 2\tfig9_convergence.csv orders.csv"),
            std::string::npos)
      << ss.str();
  const fs::path help = work / "help.txt";
  ASSERT_EQ(std::system((bin + " --help > " + help.string()).c_str()), 0);
  std::ifstream hin(help);
  std::stringstream hs;
  hs << hin.rdbuf();
  // Every key with its type, range, default (from the paper scene) and the studies that use it.
  EXPECT_NE(hs.str().find("decay.h  (a number; a finite number > 0)  default 0.3"), std::string::npos) << hs.str();
  EXPECT_NE(hs.str().find("used by: oscillator, convergence, cost"), std::string::npos);
  EXPECT_NE(hs.str().find("Exit codes"), std::string::npos);
}

// A registered method no paper here uses, named in a scene, joins Fig 9's study without a
// change to the experiment: its columns and its fitted order appear, the others' do not.
TEST(Cli, MethodNamedInTheSceneJoinsTheConvergenceStudy) {
  const fs::path out = work / "forest_ruth";
  fs::remove_all(out);
  const Outcome r = run("--quick --study convergence --set 'convergence.methods=[\"forest_ruth\", \"rk4\"]' --out " +
                        out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream csv(out / "fig9_convergence.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "h,steps,forest_ruth_max,rk4_max,forest_ruth_rms,rk4_rms,forest_ruth_evals,rk4_evals,"
                    "ee_decay_max,ee_gompertz_max");
  std::ifstream orders(out / "orders.csv");
  std::string line;
  double order = 0;
  while (std::getline(orders, line))
    if (const auto at = line.find(",forest_ruth_energy,"); at != std::string::npos)  // initial,name,order,...
      order = std::stod(line.substr(at + std::string(",forest_ruth_energy,").size()));
  EXPECT_NEAR(order, 4.0, 0.1);
}

TEST(Cli, CompensatedMethodRefusesASingularStep) {
  // (82) needs |q0| < 1 + k h^2; at q0 = 1.5, k = 2 the step h = 0.1 does not satisfy it.
  expect_rejected("--study convergence --set oscillator.q0=1.5 --set 'convergence.h=[0.1, 0.05, 0.025]'",
                  {"convergence.h", "(82)"});
}

// Only the observables the scene names are computed: without phase_error no reference solution is
// computed or written, and no phase column, order or reference check appears.
TEST(Cli, RowlandsEnergyErrorAloneComputesNoReference) {
  const fs::path out = work / "energy_only";
  fs::remove_all(out);
  const Outcome r = run("--quick --study convergence --set 'observables=[\"energy_error\"]' --out " + out.string(),
                        bin_of("rowlands_convergence"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "reference.csv"));
  std::ifstream csv(out / "fig4_convergence.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find("sv_energy_rms"), std::string::npos) << header;
  EXPECT_EQ(header.find("_phase"), std::string::npos) << header;
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  for (const auto& [key, order] : summary["orders"].items()) EXPECT_EQ(key.find("_phase"), std::string::npos) << key;
  EXPECT_FALSE(summary.contains("reproduced") && summary["reproduced"].contains("reference_self_check"));
  EXPECT_EQ(summary["comparisons"]["sv_phase"]["verdict"], "not computed");  // published, but not asked for
  EXPECT_EQ(summary["comparisons"]["sv_energy"]["verdict"], "reproduced");
}

// A former study name (Study::aliases) still selects the study, with a note on stderr naming the new
// one; the new name gets no note.
TEST(Cli, FormerStudyNamesAreAcceptedWithANote) {
  const std::vector<std::tuple<std::string, std::string, std::string>> renamed = {
      {"euler_compensation", "timing", "cost"}, {"rowlands_convergence", "timing", "cost"},
      {"energy_map", "timing", "kernel_timing"}, {"lobatto_table", "timing", "cost"},
      {"ti_drift", "work_precision", "cost"},   {"ti_drift", "timing", "kernel_timing"}};
  for (const auto& [experiment, former, now] : renamed) {
    const BinaryOutcome r = run_binary(experiment, "--quick --plan --study " + former);
    EXPECT_EQ(r.code, 0) << experiment << ": " << r.err;
    EXPECT_NE(r.out.find(now), std::string::npos) << experiment << ": " << r.out;
    EXPECT_NE(r.err.find("study '" + former + "' is now called '" + now + "'"), std::string::npos) << experiment << ": " << r.err;
    EXPECT_EQ(run_binary(experiment, "--quick --plan --study " + now).err, "") << experiment;
  }
}

}  // namespace cli_test

namespace cli_test {
namespace {

// Exit 2 with one line naming every needle, for a run of `binary` with `args` (no --quick added).
void expect_refused_raw(const std::string& args, const std::vector<std::string>& needles, const std::string& binary = bin) {
  const Outcome r = run(args, binary);
  EXPECT_RUN_REFUSED(fs::path(binary).filename().string() + " " + args, r.code, r.err, 2, needles);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace

// Scenes that would make the TOML parser recurse 50,000 deep, or read 2 MB, or block (a pipe), and paths the
// system cannot resolve: refused before parsing, exit 2, one line naming the file and why.
TEST(Cli, HostileScenesAreRefusedBeforeParsing) {
  fs::create_directories(work);
  const auto scene = [](const std::string& name, const std::string& text) {
    std::ofstream(work / name) << text;
    return (work / name).string();
  };
  std::string deep = "a", header = "[t", nest = "x = ";
  for (int i = 0; i < 50000; ++i) deep += ".a", header += ".t";
  nest += std::string(50000, '[') + std::string(50000, ']');
  expect_refused_raw("--plan --scene " + scene("deep.toml", deep + " = 1\n"), {"deep.toml:1", "more than 32 dotted components"});
  expect_refused_raw("--plan --scene " + scene("header.toml", header + "]\n"), {"header.toml:1", "more than 32 dotted components"});
  expect_refused_raw("--plan --scene " + scene("nest.toml", nest + "\n"), {"nest.toml:1", "nested more than 32 deep"});
  expect_refused_raw("--plan --scene " + scene("big.toml", std::string(2 << 20, '#')), {"big.toml", "over the 1048576 bytes"});
  expect_refused_raw("--plan --scene /dev/zero", {"/dev/zero", "not a regular file"});
  const fs::path fifo = work / "fifo.toml", loop = work / "loop.toml";
  fs::remove(fifo), fs::remove(loop);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  fs::create_symlink(loop.filename(), loop);
  expect_refused_raw("--plan --scene " + fifo.string(), {"fifo.toml", "not a regular file"});
  expect_refused_raw("--plan --scene " + loop.string(), {"loop.toml", "a loop of symbolic links"});
  expect_refused_raw("--plan --scene " + scene("based.toml", "base = \"loop.toml\"\n"), {"based.toml: base = \"loop.toml\"", "a loop of symbolic links"});
  expect_refused_raw("--plan --scene " + (work / std::string(300, 'n')).string(), {"too long"});
  // a scene within the limits (keys of 32 components, arrays nested 32 deep) reaches the parser and the schema
  std::string ok32 = "a";
  for (int i = 1; i < 32; ++i) ok32 += ".a";
  expect_refused_raw("--plan --scene " + scene("ok32.toml", ok32 + " = 1\n"), {"unknown key 'a.a.a"});
}

// --out paths that cannot become a results directory: refused before any work, naming why.
TEST(Cli, HostileOutputPathsAreRefusedBeforeWork) {
  fs::create_directories(work);
  const fs::path dangling = work / "dangling", file = work / "a-file";
  fs::remove(dangling);
  fs::create_symlink("nowhere", dangling);
  std::ofstream(file) << "x";
  expect_refused_raw("--quick --out ''", {"--out", "an empty path"});
  expect_refused_raw("--quick --out " + dangling.string(), {"dangling", "symbolic link"});
  expect_refused_raw("--quick --out " + (file / "x").string(), {"a-file/x", "Not a directory"});
  expect_refused_raw("--quick --out " + (work / std::string(250, 'n')).string(), {"with .partial it would exceed the 255"});
  EXPECT_FALSE(fs::exists(file.string() + ".lock"));
  EXPECT_EQ(fs::read_symlink(dangling), "nowhere");
}

// One run per results directory: while another process holds DIR.lock, a run on DIR exits 2 at once naming
// it, and leaves that run's DIR.partial as it was; once the lock is free the run goes ahead.
TEST(Cli, ASecondRunOnTheSameOutputIsRefusedAtOnce) {
  const fs::path out = work / "locked", partial = work / "locked.partial", lock = work / "locked.lock";
  fs::remove_all(out), fs::remove_all(partial);
  fs::create_directories(partial);
  std::ofstream(partial / ".geomint-staging") << "euler_compensation\n";
  std::ofstream(partial / "decay.csv") << "the other run's\n";
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  ASSERT_EQ(::write(fd, "424242\n", 7), 7);
  expect_refused_raw("--quick --study decay --out " + out.string(), {"another run (process 424242)", "locked.lock"});
  EXPECT_EQ(file_text(partial / "decay.csv"), "the other run's\n");
  ::close(fd);  // (the other run ends)
  const Outcome r = run("--quick --study decay --out " + out.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "run.json"));
  EXPECT_FALSE(fs::exists(lock));  // (removed by the run that held it last)
}

// SIGTERM during a study that has no checkpoint stops the run with exit 3 (README: exit codes), DIR untouched
// and its lock gone.
TEST(Cli, SigtermWithoutACheckpointExitsThree) {
  const fs::path out = work / "terminated";
  fs::remove_all(out), fs::remove_all(out.string() + ".partial");
  const std::string cmd = bin_of("ti_drift") + " --study cost --out " + out.string() + " >/dev/null 2>" +
                          (work / "term.txt").string() + " & pid=$!; sleep 1; kill -TERM $pid; wait $pid";
  fs::create_directories(work);
  const int status = std::system(("bash -c '" + cmd + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3) << file_text(work / "term.txt");
  EXPECT_NE(file_text(work / "term.txt").find("interrupted: stopped"), std::string::npos) << file_text(work / "term.txt");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".lock"));
}

}  // namespace cli_test

namespace cli_test {

// What a person reads: an argument with a newline or carriage return is refused and shown escaped on one line
// (never two keys from one --set); an unknown --study is refused with --list-keys too; a TOML date is named as
// one, a NUL inside a string shown escaped, and an integer written as a float is said to be one.
TEST(Cli, RefusalsAreOneReadableLine) {
  // (std::system runs /bin/sh: printf makes the newline and the carriage return)
  expect_refused_raw("--quick --plan --set \"$(printf 'decay.h=0.2\\nanything=1')\"", {"--set decay.h=0.2\\nanything=1", "control character"});
  expect_refused_raw("--quick --plan --study \"$(printf 'decay\\r')\"", {"--study decay\\r", "control character"});
  expect_refused_raw("--list-keys --study nope", {"--study nope", "no such study"});
  expect_refused_raw("--quick --plan --set decay.h=1979-05-27", {"decay.h = 1979-05-27 (a date or time)"});
  expect_refused_raw("--quick --plan --set 'ensemble.seed=1e3'", {"ensemble.seed = 1000", "floating-point number", "write 1000"},
                     bin_of("ti_drift"));
  expect_refused_raw("--quick --plan --set 'pendulum.l=\"a\\u0000b\"'", {"pendulum.l = \"a\\x00b\""}, bin_of("energy_map"));
}

}  // namespace cli_test

namespace cli_test {

// Steps at which the transformed variable of Figs 2-3 is undefined along the Euler run (a NaN or -inf in the
// CSV before): refused before any work, with the bound derived in decay.cpp and gompertz.cpp.
TEST(Cli, StepsWhereTheTransformedVariableIsUndefinedAreRefused) {
  expect_rejected("--study gompertz --set gompertz.h=4.0", {"gompertz.h = 4", "overshoots the equilibrium", "h > 1/b"});
  expect_rejected("--study gompertz --set gompertz.h=2.01", {"gompertz.h = 2.01", "h > 1/b = 2"});
  expect_rejected("--study decay --set decay.alpha=1e300 --set decay.h=1e-300", {"decay.h = 1e-300", "h < 1/alpha"});
}

}  // namespace cli_test

namespace cli_test {

// A frequency that overflows is named as such (not "dt < 0"); geomint-methods names what it got.
TEST(Cli, OverflowingParametersAndToolOptionsAreNamed) {
  expect_refused_raw("--quick --plan --set pendulum.k=1e300 --set pendulum.m=1e-300",
                     {"pendulum.k = 1e+300", "sqrt(k/m) = inf", "not a finite positive number"}, bin_of("energy_map"));
  expect_refused_raw("--list-keys --json", {"one option at most, here 2"}, bin_of("geomint-methods"));
  expect_refused_raw("--list-keys", {"unknown option '--list-keys'", "--json, --names, --gnuplot, --help"},
                     bin_of("geomint-methods"));
}

}  // namespace cli_test

namespace cli_test {

// Two runs on one --out at once: the second exits 2 at once naming the first's process, and the first ends
// with its complete results (never its DIR.partial deleted under it).
TEST(Cli, TwoConcurrentRunsOnOneOutput) {
  const fs::path out = work / "concurrent";
  fs::remove_all(out), fs::remove_all(out.string() + ".partial");
  fs::create_directories(work);
  const std::string first = bin_of("energy_map") + " --study map --set grid.nx=41 --set grid.ny=41 --out " + out.string();
  const std::string cmd = first + " >/dev/null 2>" + (work / "first.txt").string() + " & pid=$!; " +
                          "while [ ! -e " + out.string() + ".lock ] && kill -0 $pid 2>/dev/null; do sleep 0.01; done; " +
                          bin_of("energy_map") + " --study map --out " + out.string() + " >/dev/null 2>" +
                          (work / "second.txt").string() + "; second=$?; wait $pid; first=$?; exit $((first * 16 + second))";
  const int status = std::system(("bash -c '" + cmd + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string second = file_text(work / "second.txt");
  EXPECT_EQ(WEXITSTATUS(status) % 16, 2) << second;  // the second: refused
  EXPECT_EQ(WEXITSTATUS(status) / 16, 0) << file_text(work / "first.txt");  // the first: done
  EXPECT_NE(second.find("another run (process "), std::string::npos) << second;
  EXPECT_EQ(std::count(second.begin(), second.end(), '\n'), 1) << second;
  EXPECT_TRUE(fs::exists(out / "map.csv"));
  EXPECT_TRUE(fs::exists(out / "run.json"));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

// --timing-concurrency FILE (make figures): the first run that times measures whether the cores time alike and adds
// it to FILE; a later run reads it there (run.json timing_concurrency says which), and times by it; a FILE of another
// form is refused before any work.
TEST(Cli, TimingConcurrencyIsMeasuredOnceAndReadFromItsFile) {
  const fs::path shared = work / "timing_concurrency.txt", out = work / "concurrency";
  fs::remove(shared), fs::remove_all(out);
  const auto concurrency_of = [&](const std::string& args) {
    fs::remove_all(out);
    const Outcome r = run("--quick --study cost --threads 2 --out " + out.string() + " --timing-concurrency " + args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(file_text(out / "run.json")).at("timing_concurrency").at(0);
  };
  const auto measured = concurrency_of(shared.string());
  EXPECT_EQ(measured.at("from"), "this run");
  std::istringstream line(file_text(shared));
  int requested = 0, workers = 0;
  double slowdown = 0;
  ASSERT_TRUE(line >> requested >> workers >> slowdown) << file_text(shared);
  EXPECT_EQ(requested, 2);
  EXPECT_EQ(workers, measured.at("workers").get<int>());
  EXPECT_EQ(slowdown, measured.at("slowdown").get<double>());  // (%.17g: the same double)

  std::ofstream(shared) << "2 1 1.5\n";  // (as if measured on two hyperthreads: one configuration at a time)
  const auto read = concurrency_of(shared.string());
  EXPECT_EQ(read.at("from"), shared.string());
  EXPECT_EQ(read.at("workers"), 1);
  EXPECT_EQ(read.at("slowdown"), 1.5);

  std::ofstream(shared) << "2 3 1.5\n";  // (3 workers of 2 requested)
  expect_refused_raw("--quick --study cost --out " + out.string() + " --timing-concurrency " + shared.string(),
                     {"--timing-concurrency " + shared.string() + ", line 1", "\"2 3 1.5\"", "requested workers slowdown"});
}

// GEOMINT_LANES caps the lanes' instruction set (sweep/lanes_cap.hpp): with sse2 only the SSE2 lanes run and are
// timed, and run.json records the cap; another value is refused before any work, in one line.
TEST(Cli, LanesCapIsTheWidestInstructionSetTheLanesUse) {
  const fs::path out = work / "lanes";
  for (const std::string name : {"ti_drift", "energy_map"}) {
    fs::remove_all(out);
    const Outcome r = run("--quick --study kernel_timing --threads 2 --out " + out.string(), "GEOMINT_LANES=sse2 " + bin_of(name));
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(file_text(out / "run.json")).at("lanes_cap"), "sse2") << name;
    const auto timing = nlohmann::json::parse(file_text(out / "summary.json")).at("timing");
    if (name == "energy_map") EXPECT_EQ(timing.at("kernel_isa"), "sse2");
    if (name == "ti_drift")
      for (const char* fig : {"fig4", "fig6"}) {
        const auto& kernels = timing.at("lanes").at(fig).at("kernels");
        EXPECT_EQ(kernels.size(), 1u) << fig << ": " << kernels.dump();
        EXPECT_TRUE(kernels.contains("SSE2")) << fig << ": " << kernels.dump();
      }
  }
  expect_refused_raw("--quick --out " + out.string(), {"GEOMINT_LANES=avx1024", "avx512, avx2 or sse2"},
                     "GEOMINT_LANES=avx1024 " + bin);
}

}  // namespace cli_test

// Under a file size limit (ulimit -f) a write past it fails and the run says so (exit 1, DIR untouched), where
// SIGXFSZ used to kill it with no message.
TEST(Cli, AFileSizeLimitIsAnErrorWithAMessage) {
  namespace fs = std::filesystem;
  const fs::path out = fs::path(GEOMINT_TEST_RESULTS) / ("euler_compensation-ulimit-" + std::to_string(::getpid()));
  fs::remove_all(out), fs::remove_all(out.string() + ".partial");
  const fs::path err = out.string() + ".stderr";
  const int status = std::system(("ulimit -f 8; exec " + std::string(GEOMINT_BIN_DIR) + "/euler_compensation --quick --out " +
                                  out.string() + " >/dev/null 2>" + err.string()).c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal";
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(file_text(err).find("File too large"), std::string::npos) << file_text(err);
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(out.string() + ".partial"), fs::remove(err);
}
