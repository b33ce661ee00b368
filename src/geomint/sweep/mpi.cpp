#include "geomint/sweep/mpi.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#ifdef GEOMINT_HAVE_MPI
#include <mpi.h>
#endif

namespace geomint::mpi {

namespace {
double g_busy = 0, g_exchange = 0;
}  // namespace

void count_busy(double seconds) { g_busy += seconds; }
double busy_seconds() { return g_busy; }
void count_exchange(double seconds) { g_exchange += seconds; }
double exchange_seconds() { return g_exchange; }

#ifdef GEOMINT_HAVE_MPI

namespace {
bool g_active = false;  // MPI initialised by a Session and not yet finalised
int g_rank = 0, g_size = 1;
}  // namespace

// Started by mpirun, srun or another process manager (its environment variables): without one the
// process stays out of MPI altogether, exactly as a build without MPI.
bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(var)) return true;
  return false;
}

Session::Session(int& argc, char**& argv) {
  if (!launched_by_mpi()) return;
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  g_active = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
}

Session::~Session() {
  if (g_active) MPI_Finalize();
  g_active = false;
}

int rank() { return g_rank; }
int size() { return g_size; }
bool built_with_mpi() { return true; }

std::vector<double> all_gather(std::span<const double> mine) {
  if (g_size == 1) return {mine.begin(), mine.end()};
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(g_size)), offsets(static_cast<std::size_t>(g_size));
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::int64_t total = 0;
  for (int r = 0; r < g_size; ++r) {
    if (total > INT32_MAX) throw std::length_error("mpi::all_gather: more than 2^31 values in one round");
    offsets[static_cast<std::size_t>(r)] = static_cast<int>(total), total += counts[static_cast<std::size_t>(r)];
  }
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  return all;
}

std::int64_t all_max(std::int64_t v) {
  std::int64_t out = v;
  if (g_size > 1) MPI_Allreduce(&v, &out, 1, MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

std::int64_t all_min(std::int64_t v) {
  std::int64_t out = v;
  if (g_size > 1) MPI_Allreduce(&v, &out, 1, MPI_INT64_T, MPI_MIN, MPI_COMM_WORLD);
  return out;
}

void broadcast(std::vector<double>& v, int root) {
  if (g_size == 1) return;
  std::int64_t n = static_cast<std::int64_t>(v.size());
  MPI_Bcast(&n, 1, MPI_INT64_T, root, MPI_COMM_WORLD);
  v.resize(static_cast<std::size_t>(n));
  for (std::int64_t at = 0; at < n; at += INT32_MAX)  // in pieces that an int counts
    MPI_Bcast(v.data() + at, static_cast<int>(std::min<std::int64_t>(INT32_MAX, n - at)), MPI_DOUBLE, root, MPI_COMM_WORLD);
}

void broadcast(std::string& s, int root) {
  if (g_size == 1) return;
  std::int64_t n = static_cast<std::int64_t>(s.size());
  MPI_Bcast(&n, 1, MPI_INT64_T, root, MPI_COMM_WORLD);
  s.resize(static_cast<std::size_t>(n));
  MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, MPI_COMM_WORLD);
}

#else  // one process

Session::Session(int&, char**&) {}
Session::~Session() = default;
int rank() { return 0; }
int size() { return 1; }
bool built_with_mpi() { return false; }
std::vector<double> all_gather(std::span<const double> mine) { return {mine.begin(), mine.end()}; }
std::int64_t all_max(std::int64_t v) { return v; }
std::int64_t all_min(std::int64_t v) { return v; }
void broadcast(std::vector<double>&, int) {}
void broadcast(std::string&, int) {}

#endif

}  // namespace geomint::mpi
