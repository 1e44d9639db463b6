#pragma once
// How a derivation ended, with its statistics: what rt::derive fills in and
// what the embedding API returns (grammar.hpp), in a header of its own so
// that embedding programs need not include the scheduler's (derivation.hpp).

namespace g2d::rt {

enum class StopReason { Terminal, StepLimit };

struct DerivationResult {
    long long steps = 0;
    long long applications = 0;   // rewrites applied (a parallel step applies many)
    long long rejectedDrawings = 0;   // `layout angles`: steps whose drawing was rejected (nothing applied)
    long long rejectedByCost = 0;     // `layout angles` with a cost: proposals the Metropolis test refused (nothing applied)
    long long rejectedSplits = 0;     // `layout angles { connected = true; }`: proposals refused for splitting what they touch
    long long bendsReduced = 0;       // bent edges (edge_bends.hpp) whose bend was cut to keep the drawing planar
    long long rejectedIntersections = 0;   // `intersect`: applications undone because they would intersect the model
    StopReason stopped = StopReason::Terminal;
    double seconds = 0;
    // Picks guessed a step ahead to prefetch their records (pick_lookahead.hpp), and the right guesses.
    long long lookaheadGuesses = 0, lookaheadHits = 0;
    // Rule sets repaired after steps, and left as they were because their
    // step changed no kind or attribute their rule reads (RuleInfo::readKinds,
    // readValues).
    long long setRepairs = 0, setRepairsSkipped = 0;
    // What a grammar seldom means, counted where it happens (#47): new faces
    // left running a shared side the same way as a face already on it
    // (daughter_faces.hpp), `insert`s that found no face with their side, and
    // compound commands that found no instance when the list reached them.
    long long facesAgainstNeighbours = 0, insertsWithoutSide = 0, compoundsWithoutInstances = 0;
};

}  // namespace g2d::rt
