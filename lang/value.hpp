// Run-time values of the interpreter (spec §3): a small tagged union.
#pragma once

#include "object_schema.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace crt::lang {

struct MacroExpr;
struct Frame;
struct ModifierList;

enum class ValueKind : uint8_t {
    Unset,    ///< a variable slot not yet assigned (never visible as a value)
    Poisoned, ///< a variable whose value could not be made (the error is reported): reading it
              ///< abandons the statement, with no further error
    None,
    Int,
    Float,
    Bool,
    String,
    Vec3,
    Color,
    List,
    Entity,
    Material,
    Light,
    Camera,
    Background,
    Fog,
    Medium,
    Texture,
    BlobComponent, ///< a BlobSphere or BlobCylinder, for a Blob's components
    Spline,        ///< a Spline, read with spline(s, t)
    Function,      ///< a compiled numeric Function: index into the interpreter's functions
    Macro,
    Builtin,
    Modifiers, ///< a list of modifiers held as a value: `<rotate v, material m>`
};

struct Value;

/// A macro value: its code and the frame it closes over (null at top level).
struct Closure {
    const MacroExpr* macro;
    Frame* enclosing;
};

/// A heap-allocated macro frame, kept alive because nested macros read it.
struct Frame {
    std::vector<Value> slots;
    Frame* enclosing;
};

struct Value {
    ValueKind kind = ValueKind::Unset;
    ObjectType objectType = ObjectType::Count; ///< for object kinds; Count for CSG/groups
    union {
        int64_t i;
        double f;
        bool b;
        double v[4]; ///< vec3 x y z, color r g b a
        const std::string* s;
        const std::vector<Value>* list;
        const Closure* closure;
        const ModifierList* modifiers;
        uint32_t index; ///< objects: index into their pool; builtins: table index
    };

    Value() : i(0) {}
    static Value none() { Value r; r.kind = ValueKind::None; return r; }
    static Value integer(int64_t x) { Value r; r.kind = ValueKind::Int; r.i = x; return r; }
    static Value number(double x) { Value r; r.kind = ValueKind::Float; r.f = x; return r; }
    static Value boolean(bool x) { Value r; r.kind = ValueKind::Bool; r.b = x; return r; }
    static Value vec3(double x, double y, double z) {
        Value r;
        r.kind = ValueKind::Vec3;
        r.v[0] = x, r.v[1] = y, r.v[2] = z, r.v[3] = 0;
        return r;
    }
    static Value color(double r_, double g, double b_, double a = 1.0) {
        Value r;
        r.kind = ValueKind::Color;
        r.v[0] = r_, r.v[1] = g, r.v[2] = b_, r.v[3] = a;
        return r;
    }
    static Value string(const std::string* text) { Value r; r.kind = ValueKind::String; r.s = text; return r; }
    static Value listOf(const std::vector<Value>* items) { Value r; r.kind = ValueKind::List; r.list = items; return r; }
    static Value object(ValueKind kind, ObjectType type, uint32_t index) {
        Value r;
        r.kind = kind;
        r.objectType = type;
        r.index = index;
        return r;
    }

    bool isNumber() const { return kind == ValueKind::Int || kind == ValueKind::Float; }
    double asDouble() const { return kind == ValueKind::Int ? static_cast<double>(i) : f; }
    bool isObject() const { return kind >= ValueKind::Entity && kind <= ValueKind::Spline; }
};

/// The type's name as messages show it: "int", "vec3", "Sphere", "macro".
std::string typeName(const Value& value);
std::string_view kindName(ValueKind kind);

} // namespace crt::lang
