#pragma once
// Test only (tests/faults/every_write.py): a crash, or a stop, right after any one write a run makes to disk
// that crash safety rests on. Each such write calls fault_point() once it is done: a file written in full and
// its rename (io/atomic_file.cpp), the lock, the staging directory made, emptied or renamed into DIR, a
// checkpoint log appended, cut back or removed (runner/checkpoint.cpp). Without the variables below it does
// nothing but test a flag read once.
//   GEOMINT_FAULT_AFTER_WRITES=k     after write k the process ends at once: _exit(99), no cleanup (a crash);
//   GEOMINT_FAULT_TORN=1             with it, if write k appended to a file, the crash tears it: only the first
//                                    half of what it appended is left (a power cut in the middle of the write)
//   GEOMINT_FAULT_SIGNAL_AT_WRITE=k  after write k it raises SIGTERM (a stop asked for at that point)
//   GEOMINT_FAULT_COUNT_WRITES=FILE  at exit FILE gets a line per write: "<k> <what> <file name>"
#include <cstdint>
#include <filesystem>

namespace geomint {

void fault_point(const char* what, const std::filesystem::path& file, std::uintmax_t appended = 0);

}  // namespace geomint
