// Reads every method's settings from an empty ParamMap so that each key registers its
// default, range and documentation (for `vct render --help-params` and the README table).
#pragma once

namespace vct {
void documentAllMethodParams();
}
