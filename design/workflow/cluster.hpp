#pragma once
// The processes a spiral run spreads its tasks over (DESIGN.md §10): one
// process needs no cluster at all; under `mpirun -n N spiral run …` (spiral
// built with MPI, Debian's OpenMPI) every rank runs the same spiral — the
// same plan from the same project — and each batch of tasks is shared out:
// rank 0 owns the results store, hands the missing tasks out one at a time,
// longest kind first, to whichever rank is free (itself included, on a
// second thread), and stores each result as it arrives; at the end of the
// batch it sends every rank all the batch's results, so that every rank
// reduces the stage to the same numbers and plans the next batch alike.
//
// Not done: a rank that dies takes the job down with it (MPI's default
// error handler); its finished tasks are in the store and `spiral run`
// resumes them, threaded or under MPI.

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace spiral::design {

using Bytes = std::vector<std::uint8_t>;

class Cluster {
 public:
  virtual ~Cluster() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Rank 0's `bytes` on every rank (the others' are replaced).
  virtual void broadcast(Bytes& bytes) const = 0;
  /// Runs `work(i)` for every i of `order` (the same list on every rank),
  /// each on one rank, handed out dynamically; rank 0 receives every result
  /// with `on_result(i, bytes)` (on its calling thread, one at a time).
  /// Other ranks return when rank 0 has no work left for them.
  virtual void distribute(const std::vector<std::size_t>& order, const std::function<Bytes(std::size_t)>& work,
                          const std::function<void(std::size_t, Bytes)>& on_result) const = 0;
};

/// The MPI cluster of this process when it was started by mpirun with more
/// than one rank and spiral was built with MPI; otherwise none. Initializes
/// MPI (finalized when the cluster is destroyed).
std::unique_ptr<Cluster> launched_cluster();

/// Whether this spiral was built with MPI.
bool built_with_mpi();

}  // namespace spiral::design
