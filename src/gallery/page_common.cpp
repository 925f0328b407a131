// Parts every gallery page shares: the head (stylesheet and script are files in the site),
// the footer with tone mapping, renderer, dates and scene credits.
#include "gallery/html.h"
#include "gallery/scene_credits.h"
#include "gallery/site_images.h"
#include "gallery/site_model.h"

#include <cmath>
#include <set>
#include <sstream>

namespace vct {

double jsonNumber(const nlohmann::json& j, const char* key) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nan("");
    return j[key].get<double>();
}

std::string recordLabel(const nlohmann::json& record, bool withKind) {
    std::string label = record.value("label", record.value("method", "?"));
    return withKind ? record.value("kind", "ao") + ": " + label : label;
}

std::string pageHead(const std::string& title, const std::string& extraHead) {
    std::ostringstream s;
    s << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>" << escapeHtml(title) << "</title>\n"
      << "<link rel=\"stylesheet\" href=\"assets/gallery.css\">\n"
      << "<script src=\"assets/gallery.js\" defer></script>\n"
      << extraHead << "</head>\n";
    return s.str();
}

std::string pageFooter(const std::vector<const SiteCase*>& cases, const std::string& generated) {
    std::ostringstream s;
    std::set<std::string> renderers, scenes;
    for (const SiteCase* c : cases) {
        renderers.insert(c->input.results.value("gl_renderer", std::string("unknown renderer")));
        scenes.insert(c->input.results.value("scene", std::string("unknown scene")));
    }
    s << "<footer class=\"meta\">\n<h2>About these images</h2>\n<p class=\"tonemap\">"
      << escapeHtml(kToneMappingNote) << "</p>\n<p>Generated " << escapeHtml(generated)
      << " by <code>vct gallery</code>. GL renderer: ";
    bool first = true;
    for (const auto& r : renderers) {
        s << (first ? "" : "; ") << "<code>" << escapeHtml(r) << "</code>";
        first = false;
    }
    s << ".</p>\n<h3>Scene credits</h3>\n<ul class=\"credits\">\n";
    for (const auto& scene : scenes)
        s << "<li><code>" << escapeHtml(scene) << "</code>: " << escapeHtml(sceneCredit(scene)) << "</li>\n";
    s << "</ul>\n</footer>\n";
    return s.str();
}

}  // namespace vct
