#pragma once
// The processes of an MPI job (Open MPI; issue 17). Every rank runs the whole experiment: the
// scene, its validation and every study. The tasks of distributed_map (runner/distributed_map.hpp)
// are split across the ranks (checkpointed_map: round by round), and every rank receives every result, so that what
// follows a map is computed from the same numbers everywhere. Rank 0 alone writes files and
// speaks on stdout and stderr. Built without MPI (-DGEOMINT_MPI=OFF), or run without mpirun,
// there is one process, rank 0 of 1, and every function here is trivial.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace geomint::mpi {

// MPI_Init_thread (MPI_THREAD_FUNNELED: the OpenMP threads of a rank make no MPI calls) in the
// constructor when the process was started by mpirun (or srun), MPI_Finalize in the destructor;
// one per process, in run_experiment. A process started otherwise does not touch MPI.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

int rank();
int size();
inline bool is_root() { return rank() == 0; }
bool built_with_mpi();

// The wall time this process spent computing the tasks of its share of distributed maps, for
// run.json's rank_busy_s: how evenly the work was split.
void count_busy(double seconds);
double busy_seconds();
// The wall time this process spent exchanging the results of distributed maps (waiting for the other
// ranks, gathering, decoding), for run.json's rank_exchange_s: on the rank that finished last it is
// the cost of the exchange itself, on the others also the wait for it.
void count_exchange(double seconds);
double exchange_seconds();

// Every rank's `mine`, concatenated in rank order, on every rank (MPI_Allgatherv).
std::vector<double> all_gather(std::span<const double> mine);
// The largest and the smallest of every rank's value, on every rank (MPI_Allreduce).
std::int64_t all_max(std::int64_t v);
std::int64_t all_min(std::int64_t v);
// Rank `root`'s value on every rank (MPI_Bcast).
void broadcast(std::vector<double>& v, int root = 0);
void broadcast(std::string& s, int root = 0);

}  // namespace geomint::mpi
