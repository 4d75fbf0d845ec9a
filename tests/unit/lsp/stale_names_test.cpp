// Completion from an older analysis: when the edits since leave the names alone, it must give
// what an analysis of the current text gives; otherwise the older analysis is refused.
#include "annotations.hpp"
#include "completion.hpp"
#include "stale_names.hpp"

#include <algorithm>
#include <iterator>

using namespace crt::lsp;
using namespace crt::lsp::test;

namespace {

/// Every item with what ranks it.
std::vector<std::string> sortedLabels(const CompletionList& list) {
    std::vector<std::string> out;
    for (const CompletionItem& item : list.items) out.push_back(item.label + " | " + item.detail + " | " + item.sortText);
    std::sort(out.begin(), out.end());
    return out;
}

/// `before` is analysed; `after` (with the cursor `@`) is only lexed.
struct Edit {
    Edit(const std::string& before, const std::string& afterMarked)
        : after(afterMarked), older(analyzeCode(before)), current(lexOnly("main.crt", after.code)) {}
    std::optional<uint32_t> at() const { return sameNamesAt(*older, *current, after.point()); }
    Annotations after;
    std::shared_ptr<const Analysis> older;
    std::shared_ptr<const Analysis> current;
};

/// Completion from the older analysis must equal completion from a fresh one.
void checkSameAsFresh(const Edit& edit) {
    std::optional<uint32_t> at = edit.at();
    REQUIRE(at);
    CompletionList stale = complete(*edit.current, edit.after.point(), *edit.older, *at, testOptions());
    auto fresh = analyzeCode(edit.after.code);
    CompletionList exact = complete(*fresh, edit.after.point(), testOptions());
    CHECK(stale.replace == exact.replace);
    std::vector<std::string> fromStale = sortedLabels(stale), fromExact = sortedLabels(exact);
    std::vector<std::string> onlyStale, onlyExact;
    std::set_difference(fromStale.begin(), fromStale.end(), fromExact.begin(), fromExact.end(), std::back_inserter(onlyStale));
    std::set_difference(fromExact.begin(), fromExact.end(), fromStale.begin(), fromStale.end(), std::back_inserter(onlyExact));
    INFO("only from the older analysis: " << Catch::Detail::stringify(onlyStale));
    INFO("only from a fresh analysis: " << Catch::Detail::stringify(onlyExact));
    CHECK(onlyStale.empty());
    CHECK(onlyExact.empty());
}

const std::string kScene = "lamp = PointLight { origin -> vec3(0, 10, -10) }\n"
                           "m = Material { color -> rgb(0.5, 0.5, 0.25) }\n"
                           "ring = Macro (count, r) {\n"
                           "    for i in range(count) {\n"
                           "        Sphere { center -> vec3(r * i, 0.5, 0) radius -> 0.2 material -> m }\n"
                           "    }\n"
                           "}\n"
                           "p = vec3(1, 0.5, -1)\n"
                           "Scene { ring(4, 2.0) }\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("a changed number keeps the names: places after it shift by the length change", "[completion][stale]") {
    // The literal before the macro grows by two characters; the cursor is inside the macro,
    // whose locals are only found if the cursor is mapped back into the older text.
    std::string after = replaced(kScene, "rgb(0.5,", "rgb(0.625,");
    after = replaced(after, "radius -> 0.2 ", "radius -> 0.2 @");
    Edit edit(kScene, after);
    REQUIRE(edit.at());
    CHECK(*edit.at() == edit.after.point() - 2);
    checkSameAsFresh(edit);
    CompletionList list = complete(*edit.current, edit.after.point(), *edit.older, *edit.at(), testOptions());
    CHECK(std::any_of(list.items.begin(), list.items.end(), [](const CompletionItem& i) { return i.label == "count"; }) ==
          false); // attribute position: attributes only, as from a fresh analysis
}

TEST_CASE("the word being typed keeps the names, inside a macro too", "[completion][stale]") {
    std::string before = replaced(kScene, "vec3(r * i, 0.5, 0)", "vec3(r * i, 0.5, )");
    Edit typing(before, replaced(kScene, "vec3(r * i, 0.5, 0)", "vec3(r * i, 0.5, co@)"));
    checkSameAsFresh(typing);
    CompletionList list = complete(*typing.current, typing.after.point(), *typing.older, *typing.at(), testOptions());
    for (const char* name : {"count", "r", "i", "m", "lamp", "ring", "p"}) {
        CHECK(std::any_of(list.items.begin(), list.items.end(), [&](const CompletionItem& i) { return i.label == name; }));
    }
    // One more letter on a word the older text already had.
    Edit more(replaced(kScene, "material -> m }", "material -> m }\n        c"),
              replaced(kScene, "material -> m }", "material -> m }\n        co@"));
    checkSameAsFresh(more);
    // A statement typed at the top level, after everything.
    Edit top(kScene, kScene + "ri@");
    checkSameAsFresh(top);
}

TEST_CASE("edits that may change the names refuse the older analysis", "[completion][stale]") {
    auto refused = [](const std::string& before, const std::string& after) {
        Edit edit(before, after);
        return !edit.at().has_value();
    };
    // A new binding: assignment, loop variable, macro parameter.
    CHECK(refused(kScene, kScene + "q@ = 1\n"));
    CHECK(refused(kScene + "q = 1\n", kScene + "qq@ = 1\n"));
    CHECK(refused(kScene, replaced(kScene, "for i in", "for ii@ in")));
    CHECK(refused(kScene, replaced(kScene, "(count, r)", "(count, rr@)")));
    // Structure: a brace, a keyword, a literal of another kind, an object's type, a callee.
    CHECK(refused(kScene, replaced(kScene, "Scene { ring", "Scene { {@ ring")));
    CHECK(refused(kScene, kScene + "while@"));
    CHECK(refused(kScene, replaced(kScene, "p = vec3(1,", "p = vec3(1.5@,")));
    CHECK(refused(kScene, replaced(kScene, "m = Material", "m = Texture@")));
    CHECK(refused(kScene, replaced(kScene, "p = vec3(", "p = rgb@(")));
    // Two words changed.
    CHECK(refused(kScene, replaced(replaced(kScene, "material -> m", "material -> mm"), "r * i", "r * ii@")));
    // Another included file brings other names.
    CHECK(refused("include \"a.crt\"\n" + kScene, "include \"b.crt@\"\n" + kScene));
}

TEST_CASE("an unchanged text maps every place to itself", "[completion][stale]") {
    Edit same(kScene, replaced(kScene, "ring(4", "ring(@4"));
    REQUIRE(same.at());
    CHECK(*same.at() == same.after.point());
    checkSameAsFresh(same);
}
