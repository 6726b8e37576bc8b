#pragma once
// Full-fidelity records of the results a stage's tasks produce, for the
// results store (results_store.hpp): every field, in CBOR (RFC 8949) through
// nlohmann::json. CBOR keeps IEEE-754 doubles bit for bit, NaN and infinities
// included (JSON text would round them or turn NaN into null), so a stage
// reduced from stored records equals the stage reduced from fresh results —
// the condition for a resumed run to give the same report as an
// uninterrupted one.
//
// The record layout follows the C++ structs; kStageRecordVersion changes with
// it, and a record of another version is not read (the task runs again).

#include <cstdint>
#include <span>
#include <vector>

#include "design/analysis/static_case.hpp"
#include "design/optimization/pretension_optimizer.hpp"
#include "design/optimization/pretension_study.hpp"
#include "design/soz/soz.hpp"
#include "design/stages/advanced_stage.hpp"
#include "design/stages/stage_dynamics.hpp"
#include "design/stages/static_stage.hpp"

namespace spiral::design {

/// 2: StaticCaseResult records whether its lines carried the current (the
/// S-C levels re-solve a quick case that did not).
/// 3: StaticCaseResult has the dynamic stiffness (polyester's dynamic EA)
/// and its natural modes; the S-C storms use it.
/// 4: line and riser profiles as columns of doubles (a static case's record
/// 2.7 MB → a fraction, read without a JSON value per number).
/// 5: the coupled solver's statistics count Newton restarts on a fresh
/// matrix (engine/numerics/sundials_ida.hpp), and runs made before it took
/// their steps without them.
/// 6: a storm's channels add heave, roll, pitch and the vertical motion of
/// the riser hang-off that moves most.
/// 7: a critical case names the case whose runs it shares (shared_with).
inline constexpr int kStageRecordVersion = 7;

using RecordBytes = std::vector<std::uint8_t>;

RecordBytes encode_record(const MooringOverview& value);
RecordBytes encode_record(const StaticCaseResult& value);
RecordBytes encode_record(const SozResult& value);
RecordBytes encode_record(const StageDynamics& value);
RecordBytes encode_record(const CriticalCaseVerification& value);
RecordBytes encode_record(const OptimizationResult& value);
RecordBytes encode_record(const PretensionStudyResult& value);

/// Decodes a record of type T. Throws std::runtime_error when the bytes are
/// not a record of this version and type (a damaged or older store).
template <class T>
T decode_record(std::span<const std::uint8_t> bytes);

}  // namespace spiral::design
