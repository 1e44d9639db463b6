#pragma once
// A warning for a matched node that every daughter deletes by mistake: the
// daughter forgot `a;`, so the node goes, and with it every edge at it.
#include "sema/context.hpp"

namespace g2d::sema {

void warnForgottenNodes(Globals& g);

}  // namespace g2d::sema
