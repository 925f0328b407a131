// vct.methods(), vct.settings(), vct.aovs(): the registry (src/methods) and the renderer's
// own tables as Python lists, read from them on every call, so a method added to the
// registry reaches Python with its settings without a second list.
#include "python/bindings.h"

#include "methods/registry.h"
#include "render/plan.h"
#include "render/renderer.h"

namespace py = pybind11;

namespace vct::python {

namespace {

py::dict settingDict(const SettingDoc& d) {
    py::dict e;
    e["key"] = d.key;
    e["default"] = d.defaultValue;
    e["range"] = d.range;
    e["doc"] = d.doc;
    return e;
}

py::dict aovDict(const AovInfo& a) {
    py::dict e;
    e["name"] = a.name;
    e["channels"] = a.channels;
    e["doc"] = a.doc;
    return e;
}

py::list methods() {
    py::list out;
    for (const Method* m : registeredMethods()) {
        py::dict e;
        e["name"] = m->name;
        e["kind"] = toString(m->kind);
        e["summary"] = m->summary;
        e["ground_truth"] = m->groundTruth;
        e["lights_the_image"] = m->lightsTheImage;
        py::list settings;
        if (m->settings)
            for (const SettingDoc& d : m->settings()) settings.append(settingDict(d));
        e["settings"] = settings;
        py::list aovs;
        for (const MethodAov& a : m->aovs) aovs.append(aovDict(a.info));
        e["aovs"] = aovs;
        py::list passes;
        for (const MethodPass& p : m->passes) passes.append(std::string(p.id.name));
        e["passes"] = passes;
        out.append(e);
    }
    return out;
}

py::list settings() {
    py::list out;
    for (const SettingDoc& d : allSettingDocs()) out.append(settingDict(d));
    return out;
}

py::list aovs() {
    py::list out;
    for (const AovInfo& a : knownAovs()) out.append(aovDict(a));
    return out;
}

}  // namespace

void bindRegistry(py::module_& m) {
    m.def("methods", &methods,
          R"doc(Every registered method, AO first: dicts with name (as render(ao=...) and
render(gi=...) take it), kind ("ao" or "gi"), summary, ground_truth (the reference that compare()
scores the others against), lights_the_image, settings (dicts with key, default,
range, doc: the params= keys it reads), aovs (name, channels, doc) and passes.)doc");
    m.def("settings", &settings,
          R"doc(Every params= key a render can read, the renderer's and every method's, once each:
dicts with key, default, range and doc (what `vct render --help-params` prints).)doc");
    m.def("aovs", &aovs, R"doc(Every AOV render(aovs=...) accepts: dicts with name, channels and doc.)doc");
}

}  // namespace vct::python
