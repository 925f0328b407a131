// `vct gallery` over a sequence comparison (`vct compare --path P --frames N`) as a user meets
// it: one small comparison along a path (AO and GI methods) and one still comparison made into
// one site; the sequence page linked from the index, showing every frame of every method and
// of the reference (copied byte for byte), with its flipbook controls, one per-frame plot per
// kind and a table whose numbers are results.json's; every link inside the site; text from
// results.json escaped; a bad sequence refused before anything is written; and (when Debian's
// chromium is installed) the page loaded headless with its script run and no console errors.
#include "support/run_vct.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>

using namespace vcttest;
namespace fs = std::filesystem;

namespace {

const char* kChromium = "/usr/bin/chromium";
const int kFrames = 4;

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

struct Site {
    std::string sequenceDir, stillDir, siteDir;
    std::string caseId, stillId;  // the cases' ids: their directories' names
    nlohmann::json results;       // the sequence's results.json
    std::string failure;          // empty when every command worked
};

// One sequence compare, one still compare and one gallery of both for the whole file.
const Site& site() {
    static const Site s = [] {
        Site r;
        r.sequenceDir = freshTempDir("gallery_seq_cmp");
        r.stillDir = freshTempDir("gallery_seq_still");
        r.siteDir = freshTempDir("gallery_seq_site");
        auto c = runVct(
            "compare scenes/offscreen_overhang.gltf --size 48x32 --voxel-res 32 --ref-spp 8 --runs 1 "
            "--methods gtao,ssao-crytek --gi ssil --path scenes/paths/overhang_walk.json --frames " +
            std::to_string(kFrames) + " -o " + r.sequenceDir);
        if (c.exitCode != 0) {
            r.failure = "vct compare --path failed: " + c.output;
            return r;
        }
        auto still = runVct(
            "compare scenes/offscreen_overhang.gltf --size 32 --ref-spp 8 --runs 1 --methods gtao -o " +
            r.stillDir);
        if (still.exitCode != 0) {
            r.failure = "vct compare failed: " + still.output;
            return r;
        }
        auto g = runVct("gallery " + r.stillDir + " " + r.sequenceDir + " -o " + r.siteDir);
        if (g.exitCode != 0) r.failure = "vct gallery failed: " + g.output;
        r.caseId = fs::path(r.sequenceDir).filename().string();
        r.stillId = fs::path(r.stillDir).filename().string();
        r.results = nlohmann::json::parse(readText(r.sequenceDir + "/results.json"));
        return r;
    }();
    return s;
}

std::string sequencePage() { return readText(fs::path(site().siteDir) / (site().caseId + ".html")); }

std::string urlDecode(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size()) {
            out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

std::string htmlUnescape(std::string s) {
    for (auto [from, to] :
         {std::pair{"&amp;", "&"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&lt;", "<"}, {"&gt;", ">"}})
        for (size_t p; (p = s.find(from)) != std::string::npos;) s.replace(p, std::string(from).size(), to);
    return s;
}

// The values of one attribute over the page, decoded to the paths they name.
std::vector<std::string> attributeValues(const std::string& html, const std::string& name) {
    const std::regex attr("\\s" + name + "=\"([^\"]*)\"");
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), attr); it != std::sregex_iterator(); ++it)
        out.push_back(urlDecode(htmlUnescape((*it)[1].str())));
    return out;
}

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
    return n;
}

std::string frameName(int f) {
    char b[16];
    std::snprintf(b, sizeof b, "%04d.png", f);
    return b;
}

// A table cell as the gallery prints numbers: 4 significant digits, an en dash for none.
std::string cell(const nlohmann::json& v) {
    if (!v.is_number()) return "\xE2\x80\x93";
    char b[64];
    std::snprintf(b, sizeof b, "%.4g", v.get<double>());
    return b;
}

// The rows of a table body (between <tbody> and </tbody>, or <tfoot> .. </tfoot>) as cell texts.
std::vector<std::vector<std::string>> tableRows(const std::string& html, const std::string& tableId,
                                                const std::string& part) {
    const size_t table = html.find("id=\"" + tableId + "\"");
    if (table == std::string::npos) return {};
    const size_t from = html.find("<" + part + ">", table), to = html.find("</" + part + ">", from);
    if (from == std::string::npos || to == std::string::npos) return {};
    const std::string body = html.substr(from, to - from);
    static const std::regex row("<tr[^>]*>([\\s\\S]*?)</tr>"), td("<td[^>]*>([\\s\\S]*?)</td>"),
        tag("<[^>]*>");
    std::vector<std::vector<std::string>> rows;
    for (auto r = std::sregex_iterator(body.begin(), body.end(), row); r != std::sregex_iterator(); ++r) {
        const std::string cells = (*r)[1].str();
        std::vector<std::string> texts;
        for (auto c = std::sregex_iterator(cells.begin(), cells.end(), td); c != std::sregex_iterator(); ++c)
            texts.push_back(htmlUnescape(std::regex_replace((*c)[1].str(), tag, "")));
        rows.push_back(texts);
    }
    return rows;
}

bool isInside(const fs::path& file, const fs::path& dir) {
    const std::string f = fs::weakly_canonical(file).string(), d = fs::weakly_canonical(dir).string() + "/";
    return f.compare(0, d.size(), d) == 0;
}

// A copy of the sequence comparison with `edit` applied to its results.json (and its files).
std::string brokenCopy(const std::string& name,
                       const std::function<void(nlohmann::json&, const fs::path&)>& edit) {
    const fs::path dir = freshTempDir("gallery_seq_bad_" + name);
    fs::copy(site().sequenceDir, dir, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    nlohmann::json doc = nlohmann::json::parse(readText(dir / "results.json"));
    edit(doc, dir);
    writeText(dir / "results.json", doc.dump(2));
    return dir.string();
}

}  // namespace

TEST(GallerySequence, PageIsLinkedFromTheIndexBesideTheStillCase) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const fs::path root(s.siteDir);
    ASSERT_TRUE(fs::is_regular_file(root / (s.caseId + ".html")));
    const std::string index = readText(root / "index.html");
    EXPECT_NE(index.find("href=\"" + s.caseId + ".html"), std::string::npos)
        << "the index links the sequence";
    EXPECT_NE(index.find("<h2>Sequences</h2>"), std::string::npos);
    // The still comparison keeps its page and its place in the grid; the sequence is not in the grid.
    EXPECT_TRUE(fs::is_regular_file(root / (s.stillId + ".html")));
    const size_t grid = index.find("id=\"grid\""), gridEnd = index.find("</table>", grid);
    ASSERT_NE(grid, std::string::npos);
    const std::string gridHtml = index.substr(grid, gridEnd - grid);
    EXPECT_NE(gridHtml.find(s.stillId + ".html"), std::string::npos);
    EXPECT_EQ(gridHtml.find(s.caseId + ".html"), std::string::npos);
    // Every sequence record has its row in the index's sequence table, with its mean RMSE.
    const auto rows = tableRows(index, "sequence-records", "tbody");
    ASSERT_EQ(rows.size(), s.results["records"].size());
    for (size_t i = 0; i < rows.size(); ++i) {
        ASSERT_GE(rows[i].size(), 5u);
        EXPECT_EQ(rows[i][2], s.results["records"][i]["label"].get<std::string>());
        EXPECT_EQ(rows[i][4], cell(s.results["records"][i]["rmse_mean"]));
    }
}

TEST(GallerySequence, PageShowsEveryFrameOfEveryMethodAndOfTheReference) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const std::string page = sequencePage();
    const auto srcs = attributeValues(page, "src");
    const std::set<std::string> shown(srcs.begin(), srcs.end());
    std::vector<std::string> dirs = {"frames/reference_ao", "frames/reference_gi"};
    for (const auto& r : s.results["records"]) {
        ASSERT_TRUE(r.contains("frames_dir")) << r.dump();
        dirs.push_back(r["frames_dir"].get<std::string>());
    }
    ASSERT_EQ(dirs.size(), 5u) << "two references, three methods";
    for (const std::string& dir : dirs)
        for (int f = 0; f < kFrames; ++f) {
            const std::string rel = "data/" + s.caseId + "/" + dir + "/" + frameName(f);
            EXPECT_TRUE(shown.count(rel)) << "the page does not show " << rel;
            const fs::path copied = fs::path(s.siteDir) / rel;
            ASSERT_TRUE(fs::is_regular_file(copied)) << copied;
            EXPECT_EQ(readText(copied), readText(fs::path(s.sequenceDir) / dir / frameName(f)))
                << rel << " is not the comparison's frame";
        }
}

TEST(GallerySequence, PageHasFlipbookControlsAndOnePlotPerKind) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const std::string page = sequencePage();
    for (const std::string& needle :
         {std::string("id=\"seq-play\""), std::string("id=\"seq-readout\""), std::string("id=\"seq-fps\""),
          "<input type=\"range\" id=\"seq-frame\" min=\"0\" max=\"" + std::to_string(kFrames - 1) + "\"",
          std::string("data-frames=\"") + std::to_string(kFrames) + "\"", std::string("<script>\n(function")})
        EXPECT_NE(page.find(needle), std::string::npos) << "the page lacks " << needle;
    // One plot per kind, each with its marker line of the current frame and one line of RMSE and
    // one of instability per method of that kind.
    EXPECT_EQ(count(page, "<svg class=\"plot frame-plot\""), 2u);
    EXPECT_EQ(count(page, "class=\"frame-marker\""), 2u);
    EXPECT_NE(page.find("id=\"plot-frames-ao\""), std::string::npos);
    EXPECT_NE(page.find("id=\"plot-frames-gi\""), std::string::npos);
    EXPECT_EQ(count(page, "class=\"series\""), 2u * s.results["records"].size());
    // Offline: no network and no script but the site's own.
    EXPECT_EQ(page.find("http://"), std::string::npos);
    EXPECT_EQ(page.find("https://"), std::string::npos);
    for (const std::string& src : attributeValues(page, "src"))
        if (src.size() > 3 && src.substr(src.size() - 3) == ".js") {
            EXPECT_EQ(src, "assets/gallery.js");
        }
    // Each method's caption starts at frame 0's RMSE, and carries every frame's for the script.
    for (const auto& r : s.results["records"]) {
        std::string values;
        for (const auto& v : r["per_frame"]["rmse"]) values += (values.empty() ? "" : " ") + cell(v);
        EXPECT_NE(page.find("data-per-frame=\"" + values + "\">" + cell(r["per_frame"]["rmse"][0]) + "<"),
                  std::string::npos)
            << r["label"];
    }
}

TEST(GallerySequence, TableNumbersAreTheResults) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const std::string page = sequencePage();
    const auto rows = tableRows(page, "sequence-records", "tbody");
    const auto& records = s.results["records"];
    ASSERT_EQ(rows.size(), records.size());
    for (size_t i = 0; i < records.size(); ++i) {
        const auto& r = records[i];
        const std::vector<std::string> want = {r["label"].get<std::string>(),
                                               r["kind"].get<std::string>(),
                                               cell(r["rmse_mean"]),
                                               cell(r["rmse_worst"]),
                                               cell(r["instability"]),
                                               cell(r["temporal"]["resolution"]),
                                               cell(r["temporal"]["change_rms"]),
                                               cell(r["frame_ms"]),
                                               cell(r["time_ms"])};
        EXPECT_EQ(rows[i], want) << "row " << i;
    }
    // The reference's own instability, one row per kind it was compared for.
    const auto refRows = tableRows(page, "sequence-records", "tfoot");
    ASSERT_EQ(refRows.size(), 2u);
    const auto& ref = s.results["reference"];
    const std::string spp = " (" + ref["spp"].dump() + " spp)";
    const std::string dash = cell(nullptr);
    EXPECT_EQ(refRows[0], (std::vector<std::string>{
                              "reference AO" + spp, "ao", dash, dash, cell(ref["ao_temporal"]["instability"]),
                              cell(ref["ao_temporal"]["resolution"]), cell(ref["ao_temporal"]["change_rms"]),
                              cell(ref["ao_frame_ms"]), dash}));
    EXPECT_EQ(refRows[1], (std::vector<std::string>{
                              "reference indirect" + spp, "gi", dash, dash,
                              cell(ref["gi_temporal"]["instability"]), cell(ref["gi_temporal"]["resolution"]),
                              cell(ref["gi_temporal"]["change_rms"]), cell(ref["gi_frame_ms"]), dash}));
}

TEST(GallerySequence, EveryLinkResolvesToAFileInsideTheSite) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    int checked = 0;
    for (const std::string& page : {std::string("index.html"), s.caseId + ".html"}) {
        const fs::path file = fs::path(s.siteDir) / page;
        const std::string html = readText(file);
        for (const char* attr : {"href", "src"})
            for (const std::string& url : attributeValues(html, attr)) {
                ASSERT_FALSE(url.empty()) << page << ": empty " << attr;
                EXPECT_EQ(url.find(':'), std::string::npos) << page << ": scheme in " << url;
                const size_t hash = url.find('#');
                const std::string path = url.substr(0, hash),
                                  fragment = hash == std::string::npos ? "" : url.substr(hash + 1);
                const fs::path target = path.empty() ? file : file.parent_path() / path;
                EXPECT_TRUE(fs::is_regular_file(target)) << page << ": " << url << " does not resolve";
                EXPECT_TRUE(isInside(target, s.siteDir)) << page << ": " << url << " leaves the site";
                if (!fragment.empty() && fragment.find('=') == std::string::npos &&
                    fs::is_regular_file(target)) {
                    EXPECT_NE(readText(target).find("id=\"" + fragment + "\""), std::string::npos) << url;
                }
                ++checked;
            }
    }
    EXPECT_GT(checked, 5 * kFrames) << "the pages should refer to their frames";
}

TEST(GallerySequence, TextFromResultsIsEscaped) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const std::string dir = brokenCopy("escaped", [](nlohmann::json& doc, const fs::path&) {
        doc["records"][0]["label"] = "gtao <b>\"bold\" & 'more'</b>";
        doc["path"]["source"] = "walk<1>.json";
    });
    const std::string out = freshTempDir("gallery_seq_escaped_site") + "/site";
    auto r = runVct("gallery " + dir + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const std::string& page : {std::string("index.html"), fs::path(dir).filename().string() + ".html"}) {
        const std::string html = readText(fs::path(out) / page);
        EXPECT_EQ(html.find("<b>\"bold\""), std::string::npos) << page << ": a label is written as markup";
        EXPECT_NE(html.find("gtao &lt;b&gt;&quot;bold&quot; &amp; &#39;more&#39;&lt;/b&gt;"),
                  std::string::npos)
            << page;
    }
    const std::string page = readText(fs::path(out) / (fs::path(dir).filename().string() + ".html"));
    EXPECT_NE(page.find("walk&lt;1&gt;.json"), std::string::npos);
}

TEST(GallerySequence, ABadSequenceIsAClearErrorAndWritesNoSite) {
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    struct Bad {
        std::string name;
        std::function<void(nlohmann::json&, const fs::path&)> edit;
        std::vector<std::string> says;  // besides the results.json's path
    };
    const std::vector<Bad> bad = {
        {"short_rmse",
         [](nlohmann::json& d, const fs::path&) { d["records"][1]["per_frame"]["rmse"].erase(0); },
         {"records[1].per_frame.rmse", "3 values for 4 frames"}},
        {"long_instability",
         [](nlohmann::json& d, const fs::path&) {
             d["records"][0]["per_frame"]["instability"].push_back(0.5);
         },
         {"records[0].per_frame.instability", "4 values for 4 frames"}},
        {"no_per_frame",
         [](nlohmann::json& d, const fs::path&) { d["records"][2].erase("per_frame"); },
         {"records[2].per_frame"}},
        {"no_frames", [](nlohmann::json& d, const fs::path&) { d.erase("frames"); }, {"frames"}},
        {"text_in_rmse",
         [](nlohmann::json& d, const fs::path&) { d["records"][0]["per_frame"]["rmse"][2] = "0.1"; },
         {"records[0].per_frame.rmse[2]", "expected a number"}},
        {"frames_dir_outside",
         [](nlohmann::json& d, const fs::path&) { d["records"][0]["frames_dir"] = "../elsewhere"; },
         {"records[0].frames_dir", "not a relative path inside"}},
        {"missing_reference_frame",
         [](nlohmann::json&, const fs::path& dir) { fs::remove(dir / "frames/reference_ao/0002.png"); },
         {"frame 2 is missing", "reference_ao/0002.png"}},
    };
    for (const Bad& b : bad) {
        const std::string dir = brokenCopy(b.name, b.edit);
        const std::string out = freshTempDir("gallery_seq_bad_site_" + b.name) + "/site";
        // The good still comparison first: a bad input anywhere stops the site before it starts.
        auto r = runVct("gallery " + s.stillDir + " " + dir + " -o " + out);
        EXPECT_EQ(r.exitCode, 1) << b.name << ": " << r.output;
        EXPECT_NE(r.output.find(dir + "/results.json"), std::string::npos)
            << b.name << ": the message names the file: " << r.output;
        for (const std::string& what : b.says)
            EXPECT_NE(r.output.find(what), std::string::npos) << b.name << ": " << r.output;
        EXPECT_FALSE(fs::exists(out)) << b.name << ": a partial site was written";
    }
}

TEST(GallerySequenceBrowser, PageLoadsAndItsFlipbookRuns) {
    if (!fs::exists(kChromium))
        GTEST_SKIP() << kChromium << " is absent (scripts/install-deps.sh installs it)";
    const Site& s = site();
    ASSERT_TRUE(s.failure.empty()) << s.failure;
    const std::string dir = freshTempDir("gallery_seq_chromium");
    const std::string url = "file://" + fs::absolute(fs::path(s.siteDir) / (s.caseId + ".html")).string();
    const std::string cmd = std::string("timeout 90 ") + kChromium +
                            " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                            " --disable-background-networking --disable-component-update --disable-sync"
                            " --user-data-dir=" +
                            dir + "/profile --enable-logging=stderr --v=0 --dump-dom " + url + " > " + dir +
                            "/out.txt 2> " + dir + "/err.txt";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << readText(dir + "/err.txt");
    const std::string dom = readText(dir + "/out.txt"), log = readText(dir + "/err.txt");
    EXPECT_NE(dom.find("data-flipbook-ready=\"1\""), std::string::npos)
        << "the flipbook script did not finish";
    EXPECT_NE(dom.find("data-gallery-ready=\"1\""), std::string::npos) << "gallery.js did not finish";
    EXPECT_NE(dom.find("frame 0 / " + std::to_string(kFrames - 1)), std::string::npos);
    EXPECT_EQ(dom.find("data-js-errors"), std::string::npos);
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
        if (line.find("CONSOLE") != std::string::npos || line.find("Uncaught") != std::string::npos ||
            line.find("ERR_FILE_NOT_FOUND") != std::string::npos)
            ADD_FAILURE() << line;
}
