// Reading one object literal (spec §5): its attributes checked against the schema, then read
// by name, an absent attribute reading as the default its description struct carries.
#pragma once

#include "interpreter_impl.hpp"
#include "value_format.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/geometric.hpp>
#include <span>
#include <string>
#include <string_view>

namespace crt::lang {

/// Where item `index` of a list attribute is written: the item itself when the value is a
/// list literal, else the whole value.
SourceRange itemRange(const Expr* value, size_t index);

/// A short list of attribute slots, kept on the stack.
struct SmallSlots {
    std::array<uint8_t, kMaxAttributes> items;
    uint8_t count = 0;
    void push_back(uint8_t slot) { items[count++] = slot; }
    const uint8_t* begin() const { return items.data(); }
    const uint8_t* end() const { return items.data() + count; }
};

/// Checks the attributes of one object literal and reads them. Every reader takes the value
/// to return when the attribute is absent: callers pass the field of a default-constructed
/// description, so that the scene description's defaults are the only ones (a unit test
/// checks the schema's documented defaults against them).
struct ObjectBuilder {
    ObjectBuilder(Interpreter& interpreter, const ObjectInfo& objectInfo, SourceRange whole,
                  SourceRange type)
        : in(interpreter), info(objectInfo), range(whole), typeRange(type) {}

    Interpreter& in;
    const ObjectInfo& info;
    SourceRange range;     ///< the whole literal
    SourceRange typeRange; ///< its type name (for Settings, the keyword)
    /// Storage for the given attributes' values and where each is written; a slot is valid
    /// where `givenMask` has its bit. Left uninitialised: building an object must not pay for
    /// clearing every slot.
    union RawValue {
        Value value;
        RawValue() {}
    };
    std::array<RawValue, kMaxAttributes> values;
    std::array<const Attribute*, kMaxAttributes> given;
    static_assert(kMaxAttributes <= 32, "givenMask has a bit a slot");
    uint32_t givenMask = 0;
    SmallSlots givenSlots; ///< the slots that are given, in the order first given

    bool isGiven(size_t slot) const { return (givenMask >> slot) & 1u; }

    /// Evaluates and checks every attribute, then reports each required one missing; throws
    /// EvalError after all of them if any failed or is missing.
    void evaluate(std::span<const Attribute> attributes);

    // --- reading ---
    /// The slot of attribute `name` if the literal gives it, else -1. Only the given
    /// attributes (usually a few) are compared, shortest test first: building objects
    /// asks for every attribute by name, and most are not given.
    int slot(std::string_view name) const {
        for (uint8_t given : givenSlots) {
            std::string_view candidate = info.attributes[given].name;
            if (candidate.size() == name.size() && candidate[0] == name[0] && candidate == name) {
                return given;
            }
        }
        return -1;
    }
    const Value* get(std::string_view name) const {
        int s = slot(name);
        return s >= 0 ? &values[static_cast<size_t>(s)].value : nullptr;
    }
    /// Where attribute `name`'s value is written, or the type name when it is absent.
    SourceRange where(std::string_view name) const {
        int s = slot(name);
        return s >= 0 ? given[static_cast<size_t>(s)]->value->range : typeRange;
    }
    /// Where item `index` of list attribute `name` is written (the type name when absent).
    SourceRange whereItem(std::string_view name, size_t index) const {
        int s = slot(name);
        return s >= 0 ? itemRange(given[static_cast<size_t>(s)]->value, index) : typeRange;
    }
    double number(std::string_view name, double absent) const {
        const Value* v = get(name);
        return v ? v->asDouble() : absent;
    }
    int64_t integer(std::string_view name, int64_t absent) const {
        const Value* v = get(name);
        return v ? v->i : absent;
    }
    bool flag(std::string_view name, bool absent) const {
        const Value* v = get(name);
        return v ? v->b : absent;
    }
    glm::dvec3 vec(std::string_view name, glm::dvec3 absent) const {
        const Value* v = get(name);
        return v ? glm::dvec3{v->v[0], v->v[1], v->v[2]} : absent;
    }
    scene::Color color(std::string_view name, scene::Color absent) const {
        const Value* v = get(name);
        return v ? scene::Color{v->v[0], v->v[1], v->v[2], v->v[3]} : absent;
    }
    /// A colour map attribute (checked: stops of [number, colour]).
    std::vector<scene::ColorStop> colorMap(std::string_view name,
                                           std::vector<scene::ColorStop> absent) const {
        const Value* v = get(name);
        if (!v) return absent;
        std::vector<scene::ColorStop> stops;
        for (const Value& stop : *v->list) {
            const Value& c = (*stop.list)[1];
            stops.push_back({(*stop.list)[0].asDouble(), {c.v[0], c.v[1], c.v[2], c.v[3]}});
        }
        return stops;
    }
    /// A float or vec3 attribute as a vec3 (a float on every axis).
    glm::dvec3 floatOrVec(std::string_view name, glm::dvec3 absent) const {
        const Value* v = get(name);
        if (!v) return absent;
        return v->kind == ValueKind::Vec3 ? glm::dvec3{v->v[0], v->v[1], v->v[2]}
                                          : glm::dvec3(v->asDouble());
    }
    std::string text(std::string_view name, const std::string& absent) const {
        const Value* v = get(name);
        return v && v->kind == ValueKind::String ? *v->s : absent;
    }
    /// A given string attribute in lower case (choices ignore case); "" when absent.
    std::string lowerText(std::string_view name) const {
        std::string t = text(name, std::string());
        std::transform(t.begin(), t.end(), t.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        return t;
    }
    /// The index of a given object attribute (a material, a texture) in its pool, else `absent`.
    int32_t index(std::string_view name, int32_t absent) const {
        const Value* v = get(name);
        return v ? static_cast<int32_t>(v->index) : absent;
    }

    // --- checks of values the schema's types allow ---
    /// A radius-like attribute, if given, must not be negative.
    void nonNegative(std::string_view name) {
        double given = number(name, 0);
        if (given < 0) {
            in.fail(where(name), fmt::format("attribute '{}' of {} is negative ({})", name,
                                             info.name, formatFloat(given)));
        }
    }
    /// A direction attribute, if given, must not be zero.
    void nonZeroVector(std::string_view name, std::string_view what) {
        if (get(name) && glm::length(vec(name, glm::dvec3(0.0))) == 0) {
            in.fail(where(name), fmt::format("attribute '{}' of {} is a zero vector; {}", name,
                                             info.name, what));
        }
    }

  private:
    void check(const Attribute& a, const Value& v);
    void checkNumber(const Attribute& a, const Value& v, AttrType type);
    void checkReference(const Attribute& a, const Value& v, AttrType type);
    void checkGamma(const Attribute& a, const Value& v);
    void checkAperture(const Attribute& a, const Value& v, const AttributeInfo& attr);
    void checkChoice(const Attribute& a, const Value& v, const AttributeInfo& attr);
    void checkMap(const Attribute& a, const Value& v, AttrType type);
    void checkMaterialList(const Attribute& a, const Value& v);
    void checkPatternList(const Attribute& a, const Value& v);
    void checkSolidList(const Attribute& a, const Value& v);
    bool isSolid(const Value& v) const;
    void missing(const AttributeInfo& attr);
    [[noreturn]] void wrongType(const Attribute& a, const Value& v, std::string_view wanted);
    /// The error of a value that is not a solid where one must be (`subject`: "attribute 'by'
    /// of Clipped", "item 2 of 'objects'"), naming an open edge when it is a Mesh.
    [[noreturn]] void notSolid(SourceRange where, std::string_view subject, const Value& v);
    [[noreturn]] void floatForInt(const Attribute& a, const Value& v, std::string_view wanted);
    void finite(const Attribute& a, const Value& v, int components);
};

/// The curve kind attribute `attribute` names (the schema has checked it is one of them).
scene::SplineKind splineKind(ObjectBuilder& b, std::string_view attribute);

} // namespace crt::lang
