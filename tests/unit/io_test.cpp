#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "geomint/io/atomic_file.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/sweep/parallel_map.hpp"

using namespace geomint;
namespace fs = std::filesystem;

TEST(Csv, HeaderRowsAndFullPrecision) {
  Csv csv({"name", "h", "n"});
  csv.row("se", 0.1, 10);
  csv.row("rk4", 1.0 / 3.0, std::int64_t{1} << 40);
  EXPECT_EQ(csv.str(), "name,h,n\nse,0.10000000000000001,10\nrk4,0.33333333333333331,1099511627776\n");
  EXPECT_EQ(std::strtod(format_double(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);  // reads back bit for bit
  EXPECT_EQ(csv.rows(), 2u);
  EXPECT_EQ(format_double(-std::nan("")), "nan");
}

TEST(Csv, RejectsRowsOfTheWrongWidth) {
  Csv csv({"a", "b"});
  EXPECT_THROW(csv.row(1.0), std::logic_error);
  Csv csv2({"a"});
  EXPECT_THROW(csv2.row(1.0, 2.0), std::logic_error);
  EXPECT_THROW(csv2.row("x,y"), std::logic_error);
}

TEST(OutputDir, WritesAtomicallyAndLeavesNoTemporaries) {
  const fs::path dir = fs::temp_directory_path() / ("geomint_io_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  OutputDir out(dir);
  out.write("a.csv", "x\n1\n");
  out.write("a.csv", "x\n2\n");
  std::ifstream in(dir / "a.csv");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "x\n2\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  EXPECT_EQ(out.written(), std::vector<std::string>{"a.csv"});
  fs::remove_all(dir);
}

TEST(OutputDir, RejectsUnwritableDirectories) {
  EXPECT_THROW(OutputDir("/proc/self/geomint-out"), OutputError);
  const fs::path file = fs::temp_directory_path() / ("geomint_io_file_" + std::to_string(::getpid()));
  std::ofstream(file) << "x";
  EXPECT_THROW(OutputDir(file / "sub"), OutputError);  // parent is a file
  fs::remove(file);
  if (::geteuid() != 0) {  // permission bits do not stop root
    const fs::path ro = fs::temp_directory_path() / ("geomint_io_ro_" + std::to_string(::getpid()));
    fs::create_directories(ro);
    ::chmod(ro.c_str(), 0555);
    EXPECT_THROW(OutputDir{ro}, OutputError);
    ::chmod(ro.c_str(), 0755);
    fs::remove_all(ro);
  }
}

TEST(ParallelMap, ResultsByIndexAndLowestIndexErrorWins) {
  const auto v = parallel_map(100, [](std::size_t i) { return static_cast<double>(i) * 0.5; });
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], 0.5 * static_cast<double>(i));
  try {
    parallel_map(50, [](std::size_t i) -> int {
      if (i % 7 == 3) throw std::runtime_error("bad " + std::to_string(i));
      return 0;
    });
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad 3");
  }
}
