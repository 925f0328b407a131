#include "methods/registry.h"

#include "ao/alchemy/alchemy.h"
#include "ao/gtao/gtao.h"
#include "ao/hbao/hbao.h"
#include "ao/horizon/horizon_ao.h"
#include "ao/ssao/ssao.h"
#include "ao/vbao/vbao.h"
#include "denoised/denoised_methods.h"
#include "reference/reference_methods.h"
#include "ssil/ssil.h"
#include "vct/vct_method.h"

namespace vct {

const std::vector<const Method*>& registeredMethods() {
    static const std::vector<const Method*> methods = {
        &ssaoCrytekMethod(),
        &ssaoHemisphereMethod(),
        &horizonMethod(),
        &alchemyMethod(),
        &hbaoMethod(),
        &gtaoMethod(),
        &vbaoMethod(),
        &vctAoMethod(),
        &rtaoDenoisedMethod(),
        &referenceAoMethod(),
        &vctGiMethod(),
        &ssilMethod(),
        &ptDenoisedMethod(),
        &referenceGiMethod(),
    };
    return methods;
}

const Method* findMethod(MethodKind kind, const std::string& name) {
    for (const Method* m : registeredMethods())
        if (m->kind == kind && m->name == name) return m;
    return nullptr;
}

const Method* requireMethod(MethodKind kind, const std::string& name, const std::string& option) {
    if (name == kNoMethod) return nullptr;
    if (const Method* m = findMethod(kind, name)) return m;
    std::string all;
    for (const std::string& n : methodNames(kind)) all += (all.empty() ? "" : ", ") + n;
    throw UsageError(option + " '" + name + "': expected one of " + all);
}

std::vector<std::string> methodNames(MethodKind kind) {
    std::vector<std::string> names{kNoMethod};
    for (const Method* m : registeredMethods())
        if (m->kind == kind) names.push_back(m->name);
    return names;
}

const Method& groundTruthMethod(MethodKind kind) {
    for (const Method* m : registeredMethods())
        if (m->kind == kind && m->groundTruth) return *m;
    throw InternalError("groundTruthMethod", std::string("no ground truth for ") + toString(kind));
}

std::vector<const Method*> scoredMethods(MethodKind kind) {
    std::vector<const Method*> out;
    for (const Method* m : registeredMethods())
        if (m->kind == kind && !m->groundTruth) out.push_back(m);
    return out;
}

}  // namespace vct
