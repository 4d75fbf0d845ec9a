// The glyphs of a Text, laid out while the script is evaluated: a font that cannot be read
// is an error of the script at its `font ->` attribute, a character the font lacks a warning
// at its `text ->`, so `crtc --check` and the language server report them, and the renderer
// draws the outlines that were checked.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

#include "scene/utf8.hpp"
#include "string_escape.hpp"

#include <filesystem>

namespace crt::lang {

namespace {

size_t characterCount(std::string_view text) {
    size_t count = 0;
    for (size_t at = 0; at < text.size(); ++count) {
        char32_t code;
        at += std::max<size_t>(1, scene::decodeUtf8(text, at, code));
    }
    return count;
}

std::string describeCharacter(char32_t code) {
    std::string shown;
    if (code >= 0x20 && code != 0x7F) appendUtf8(shown, code);
    return shown.empty() ? fmt::format("U+{:04X}", static_cast<uint32_t>(code))
                         : fmt::format("'{}' (U+{:04X})", shown, static_cast<uint32_t>(code));
}

} // namespace

scene::Shape Interpreter::textShape(ObjectBuilder& b) {
    auto desc = std::make_shared<scene::TextDesc>();
    desc->text = b.text("text", desc->text);
    desc->font = b.text("font", desc->font);
    desc->thickness = b.number("thickness", desc->thickness);
    desc->spacing = b.number("spacing", desc->spacing);
    if (desc->thickness < 0)
        fail(b.where("thickness"),
             fmt::format("a Text's thickness cannot be negative ({:g})", desc->thickness));
    if (desc->spacing < 0)
        fail(b.where("spacing"),
             fmt::format("a Text's spacing cannot be negative ({:g})", desc->spacing));
    const size_t length = characterCount(desc->text);
    if (length > options_.limits.maxTextLength) {
        fail(b.where("text"),
             fmt::format("this Text has {} characters, more than the limit of {}; raise it with "
                         "--max-text-length",
                         length, options_.limits.maxTextLength));
    }
    if (!options_.checkFiles) return scene::TextShape{std::move(desc)};
    if (desc->font.empty()) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(scene::kDefaultFontFile, error)) {
            fail(b.typeRange,
                 fmt::format("the default font, DejaVu Sans ({}), is not installed: install "
                             "Debian's fonts-dejavu-core, or name a font with 'font ->'",
                             scene::kDefaultFontFile));
        }
        desc->resolvedFont = scene::kDefaultFontFile;
    } else {
        desc->resolvedFont = findFile(b, "font", "font");
    }
    std::error_code error;
    const uintmax_t fileSize = std::filesystem::file_size(desc->resolvedFont, error);
    if (!error) checkRoom(fileSize); // FreeType holds the font while the text is laid out
    std::string problem;
    std::optional<scene::TextOutline> outline =
        scene::layoutText(desc->resolvedFont, desc->text, desc->spacing, problem);
    if (!outline) {
        const SourceRange where = desc->font.empty() ? b.typeRange : b.where("font");
        fail(where, fmt::format("bad font '{}': {}",
                                desc->font.empty() ? desc->resolvedFont : desc->font, problem));
    }
    if (!outline->missing.empty()) {
        std::string missing;
        for (char32_t code : outline->missing)
            missing += (missing.empty() ? "" : ", ") + describeCharacter(code);
        warnOnce(
            WarningKind::MissingGlyph, b.where("text"),
            fmt::format("the font has no glyph for {}: drawn as its missing-glyph shape", missing));
    }
    charge(outline->byteSize());
    desc->outline = std::make_shared<const scene::TextOutline>(std::move(*outline));
    return scene::TextShape{std::move(desc)};
}

} // namespace crt::lang
