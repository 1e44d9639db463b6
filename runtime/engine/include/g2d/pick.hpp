#pragma once
// How a rule picks among its matches: at random (weighted by nothing), or
// the oldest: the match whose elements have the lowest mean age (the step
// that created them: the thesis's age), or the lowest mean generation (the
// thesis tool's `.generation`: one more than the highest among the matched
// elements of the application that created them).
namespace g2d::rt {

enum class Pick { Random, Oldest, OldestGeneration };

constexpr bool picksOldest(Pick p) { return p != Pick::Random; }

}  // namespace g2d::rt
