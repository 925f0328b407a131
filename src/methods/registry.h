// The one list of every method the renderer can run (core/method.h). The command line, the
// planner, --help-params, compare and sweeps all read it; nothing else lists methods.
#pragma once

#include "core/method.h"

#include <string>
#include <vector>

namespace vct {

// Every method, AO first, in the order help texts and comparisons list them.
const std::vector<const Method*>& registeredMethods();

// The method `name` of `kind`, or null (also for "none").
const Method* findMethod(MethodKind kind, const std::string& name);
// findMethod, or a UsageError naming `option` ("--ao") and the accepted names.
const Method* requireMethod(MethodKind kind, const std::string& name, const std::string& option);
// The names --ao / --gi accept, "none" first.
std::vector<std::string> methodNames(MethodKind kind);
// The ground truth of `kind` (the reference), which comparisons score the others against.
const Method& groundTruthMethod(MethodKind kind);
// The methods of `kind` a comparison scores by default: every one but the ground truth.
std::vector<const Method*> scoredMethods(MethodKind kind);

}  // namespace vct
