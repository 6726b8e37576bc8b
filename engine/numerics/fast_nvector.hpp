#pragma once
// Internal to the IDA and CVODE adapters (sundials_ida.cpp,
// sundials_cvode.cpp), not a public engine API: the operations of the serial
// N_Vector, compiled here, split over a worker pool for large states
// (IdaOptions::vector_pool) and with the block error norms of
// IdaOptions::error_group_starts.
//
// Why compiled here: the Debian SUNDIALS 6.4.1 libraries are built without
// optimisation (-O0), and IDA spends most of its own time in these loops
// (docs/decisions/fe-line-dynamics-integrator.md). The operations are
// installed in the ops table of the state vector before IDAInit, so every
// vector IDA and its Newton solver clone from it uses them. Semantics as in
// nvector_serial.c (SUNDIALS 6.4.1); elementwise, so any output may alias an
// input.

#include <Eigen/Core>
#include <nvector/nvector_serial.h>

#include <vector>

namespace spiral::engine {
class WorkerPool;
}  // namespace spiral::engine

namespace spiral::engine::fast_nvector {

/// The data of a serial N_Vector as an Eigen vector (no copy).
inline Eigen::Map<Eigen::VectorXd> vec(N_Vector v) { return {NV_DATA_S(v), static_cast<Eigen::Index>(NV_LENGTH_S(v))}; }

/// The arithmetic of the operations: vectorized (Eigen's order of the
/// reductions; the large states of IDA), or the library's own
/// (nvector_serial.c's special cases of the linear sum, and the reductions as
/// one running sum in index order: CVODE's small hull states, whose adaptive
/// step sequence then reproduces the library's bit for bit).
enum class Arithmetic { vectorized, library };

/// Installs the operations in the ops table of `v`. The block error norms
/// (set_solve_context) apply to the vectorized arithmetic only.
void install(N_Vector v, Arithmetic arithmetic = Arithmetic::vectorized);

/// What the operations of the IDASolve running on this thread use: the pool
/// they split over (null: none) and the block error norms' group starts
/// (null: one group). Set around each IDASolve, cleared (null, null) after it.
void set_solve_context(WorkerPool* pool, const std::vector<Eigen::Index>* error_groups);

}  // namespace spiral::engine::fast_nvector
