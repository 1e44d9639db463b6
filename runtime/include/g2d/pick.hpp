#pragma once
// How a rule picks among its matches: at random (weighted by nothing), or
// the oldest (the match whose elements were created earliest).
namespace g2d::rt {

enum class Pick { Random, Oldest };

}  // namespace g2d::rt
