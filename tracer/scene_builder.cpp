// Builds the render scene from a SceneDesc: flattens transforms, groups and top-level
// unions into primitives, rebalances CSG chains, reads meshes, and builds the BVH.
#include "tracer/render_scene.hpp"

#include "scene/instancing.hpp"
#include "scene/mesh_file.hpp"
#include "scene/primitive_count.hpp"
#include "tracer/height_grid_reading.hpp"
#include "tracer/worker_threads.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <span>

namespace crt::tracer {

// The scene's objects and a mesh's triangles are BVH items: numbers below WideChild::kMaxItems.
// The primitive limit keeps primitives and instances below theirs; CSG nodes (which inverses
// may multiply) are counted.
constexpr size_t kMostCsgNodes = RenderScene::kFirstInstanceObject - RenderScene::kFirstCsgObject;
static_assert(scene::RenderLimits::kMostPrimitives < RenderScene::kFirstCsgObject);
static_assert(RenderScene::kFirstInstanceObject + scene::RenderLimits::kMostPrimitives < WideChild::kMaxItems);

// Runs of fewer plain roots (RenderSceneBuilder::plainRoot) are drawn on one thread: a
// thread of their own would cost more than they take.
constexpr size_t kParallelRoots = 8192;

class RenderSceneBuilder {
public:
    RenderSceneBuilder(const scene::SceneDesc& desc, RenderScene& scene, unsigned threads, std::string& error)
        : desc_(desc), scene_(scene), root_(scene), threads_(threads), error_(error), shared_(ownShared_) {}

    /// A builder of a prototype of `parent`'s scene: its parts with no material get -1 (the
    /// instance gives it), and it draws no instances of its own.
    RenderSceneBuilder(RenderSceneBuilder& parent, RenderScene& prototype)
        : desc_(parent.desc_), scene_(prototype), root_(parent.root_), threads_(parent.threads_),
          error_(parent.error_), shared_(parent.shared_), defaultMaterial_(-1), instancing_(false) {}

    bool build() {
        error_.clear(); // a mesh that cannot be read says so here
        scene_.materials.reserve(desc_.materials.size() + 1);
        for (const scene::MaterialDesc& m : desc_.materials) {
            scene_.materials.push_back({desc_.finishOf(m), m.color});
        }
        defaultMaterial_ = static_cast<int32_t>(scene_.materials.size());
        scene_.materials.emplace_back(); // the default material
        scene_.blends = desc_.blends;
        scene_.media = desc_.media;
        // Counted before anything is expanded (a shared entity doubled in a loop would
        // otherwise fill memory here), by the rule the front end counts by. Evaluation refuses
        // such a scene already, and leaves its count in the description; this is for
        // descriptions made otherwise.
        shared_.storage = desc_.storage;
        if (!shared_.storage)
            shared_.storage = std::make_shared<const scene::SceneStorage>(scene::storageOf(desc_));
        const uint64_t stored = shared_.storage->stored();
        if (stored > desc_.limits.maxPrimitives) {
            error_ = fmt::format("the scene stores more than {} primitives; raise the limit "
                                 "with --max-primitives",
                                 desc_.limits.maxPrimitives);
            return false;
        }
        // Room for them from the start (a mesh drawn is one primitive, an instance none): a
        // vector growing by doubling would copy and fault in its elements about twice.
        shared_.storedPrimitives = stored;
        const uint64_t copied = shared_.storage->copied;
        scene_.primitives.reserve(copied);
        scene_.primitiveEntities.reserve(copied);
        objects_.reserve(copied + shared_.storage->instances);
        if (!addRoots()) return false;
        finishAcceleration();
        return true;
    }

private:
    using ModifierSteps = std::vector<std::vector<scene::Modifier>>;

    struct Operand {
        int32_t entity;
        /// Below a transform node that moves (scene::MotionDesc): what is above it, which
        /// stays, and the modifiers from it down at every motion step (a MovingTransform).
        Transform transform;
        std::shared_ptr<const ModifierSteps> motion;
        int32_t material = -1; ///< given by a transform above to the parts that have none
        uint8_t hidden = 0;    ///< what the entities above it hide it from (scene::HiddenFrom)

        /// A part of `node`, this operand's entity.
        Operand part(const scene::EntityDesc& node, int32_t child) const {
            return {child, transform, motion, material, static_cast<uint8_t>(hidden | node.hidden)};
        }
    };

    /// Where the transform node `op` leads: its child, moved, maybe with a material to give.
    Operand below(const Operand& op, const scene::EntityDesc& node, const scene::TransformNode& t) const {
        Operand child = op.part(node, t.child);
        if (node.material >= 0) child.material = node.material;
        auto moving = desc_.motion.transforms.find(op.entity);
        if (moving == desc_.motion.transforms.end() && !op.motion) {
            child.transform = op.transform.compose(Transform::fromModifiers(t.modifiers));
            return child;
        }
        // The node's modifiers at each step, then those of the moving nodes above it.
        const size_t steps = op.motion ? op.motion->size() : moving->second.size();
        auto chain = std::make_shared<ModifierSteps>(steps);
        for (size_t k = 0; k < steps; ++k) {
            std::vector<scene::Modifier>& modifiers = (*chain)[k];
            modifiers = moving != desc_.motion.transforms.end() ? moving->second[k] : t.modifiers;
            if (op.motion) modifiers.insert(modifiers.end(), (*op.motion)[k].begin(), (*op.motion)[k].end());
        }
        child.motion = std::move(chain);
        return child;
    }

    /// Draws every root of the description, runs of plain roots on the build's threads.
    bool addRoots() {
        const std::vector<int32_t>& roots = desc_.drawn;
        for (size_t begin = 0; begin < roots.size();) {
            size_t end = begin;
            while (end < roots.size() && plainRoot(roots[end])) ++end;
            if (end - begin >= kParallelRoots) {
                addPlainRoots(std::span(roots).subspan(begin, end - begin));
            } else {
                for (size_t i = begin; i < end; ++i)
                    if (!addDrawn(roots[i], Transform())) return false;
            }
            if (end < roots.size() && !addDrawn(roots[end], Transform())) return false;
            begin = end + 1;
        }
        return true;
    }

    /// Whether the entity, drawn as a root, is one primitive made from its own parameters
    /// alone: one of the simple shapes scenes draw by the thousand, not instanced and hidden
    /// from nothing.
    bool plainRoot(int32_t entity) const {
        const scene::EntityDesc& e = desc_.entities[static_cast<size_t>(entity)];
        if (e.hidden != 0 || instanced(entity)) return false;
        return std::visit(
            [](const auto& shape) {
                using S = std::decay_t<decltype(shape)>;
                return std::is_same_v<S, scene::SphereShape> || std::is_same_v<S, scene::BoxShape> ||
                       std::is_same_v<S, scene::CylinderShape> || std::is_same_v<S, scene::ConeShape> ||
                       std::is_same_v<S, scene::TorusShape> || std::is_same_v<S, scene::DiscShape> ||
                       std::is_same_v<S, scene::QuadShape> || std::is_same_v<S, scene::TriangleShape> ||
                       std::is_same_v<S, scene::SuperellipsoidShape>;
            },
            e.shape);
    }

    /// Draws plain roots (plainRoot), one primitive each, made on up to threads_ threads into
    /// the places drawing them one by one gives them.
    void addPlainRoots(std::span<const int32_t> roots) {
        auto primitiveOf = [&](int32_t root) {
            const scene::Shape& shape = desc_.entities[static_cast<size_t>(root)].shape;
            return Primitive{*makeGeometry(shape, desc_.limits), -1, materialOf(root, -1)};
        };
        // Room made with a sphere, which a Geometry holds inline: no allocation to undo.
        const Primitive placeholder{SphereGeometry(scene::SphereShape{}), -1, 0};
        const size_t first = scene_.primitives.size();
        scene_.primitives.resize(first + roots.size(), placeholder);
        scene_.primitiveEntities.insert(scene_.primitiveEntities.end(), roots.begin(), roots.end());
        const size_t parts = std::clamp<size_t>(roots.size() / kParallelRoots, 1, std::max(threads_, 1u));
        runOnThreads(parts, [&](size_t part) {
            const size_t end = roots.size() * (part + 1) / parts;
            for (size_t i = roots.size() * part / parts; i < end; ++i)
                scene_.primitives[first + i] = primitiveOf(roots[i]);
        });
        markHidden(scene_.hiddenPrimitives, scene_.primitives.size(), 0);
        for (size_t i = 0; i < roots.size(); ++i) objects_.push_back(static_cast<int32_t>(first + i));
    }

    /// Draws an entity: groups and unions are drawn as their members (a union keeps every
    /// surface, so at the top level it is no different from drawing both operands); an entity
    /// drawn often enough is an instance of its prototype.
    bool addDrawn(int32_t root, const Transform& rootTransform) {
        std::vector<Operand> pending{{root, rootTransform, nullptr}};
        while (!pending.empty()) {
            Operand op = std::move(pending.back());
            pending.pop_back();
            const scene::EntityDesc& e = desc_.entities[op.entity];
            if (instanced(op.entity)) {
                if (!addInstance(op)) return false;
            } else if (auto* t = std::get_if<scene::TransformNode>(&e.shape)) {
                Operand child = below(op, e, *t);
                // Many primitives that move together are an instance of their prototype: a
                // ray is moved into it once, and meets a tree built where they stand still,
                // rather than each primitive's bounds swept over the shutter.
                if (child.motion && instancing_ &&
                    shared_.storage->expansion[static_cast<size_t>(child.entity)] >= scene::kMinInstancePrimitives) {
                    if (!addInstance(child)) return false;
                } else {
                    pending.push_back(std::move(child));
                }
            } else if (auto* g = std::get_if<scene::GroupNode>(&e.shape)) {
                for (auto it = g->members.rbegin(); it != g->members.rend(); ++it)
                    pending.push_back(op.part(e, *it));
            } else if (auto* c = std::get_if<scene::CsgNode>(&e.shape); c && c->op == scene::CsgOp::Union) {
                pending.push_back(op.part(e, c->right));
                pending.push_back(op.part(e, c->left));
            } else if (std::holds_alternative<scene::CsgNode>(e.shape) ||
                       std::holds_alternative<scene::InverseNode>(e.shape)) {
                int32_t node = addCsg(op);
                if (!error_.empty()) return false; // a mesh operand that cannot be read
                if (scene_.csgNodes.size() > kMostCsgNodes) {
                    error_ = fmt::format("the scene's CSG trees take more than {} nodes", kMostCsgNodes);
                    return false;
                }
                if (node >= 0) objects_.push_back(RenderScene::csgObject(node));
            } else {
                int32_t p = addPrimitive(op);
                if (!error_.empty()) return false; // a mesh that cannot be read
                if (p >= 0) objects_.push_back(p);
            }
        }
        return true;
    }

    int32_t materialOf(const Operand& op) const { return materialOf(op.entity, op.material); }
    /// An entity's material: its own, or the one given from above (-1: none), or the default.
    int32_t materialOf(int32_t entity, int32_t given) const {
        const int32_t own = desc_.entities[static_cast<size_t>(entity)].material;
        return own >= 0 ? own : given >= 0 ? given : defaultMaterial_;
    }

    bool instanced(int32_t entity) const {
        return instancing_ && shared_.storage->instanced[static_cast<size_t>(entity)];
    }

    /// Draws the entity as an instance of its prototype (built on its first drawing).
    bool addInstance(const Operand& op) {
        auto known = shared_.prototypes.find(op.entity);
        if (known == shared_.prototypes.end()) {
            auto prototype = std::make_unique<RenderScene>();
            RenderSceneBuilder builder(*this, *prototype);
            if (!builder.addDrawn(op.entity, Transform())) return false;
            builder.finishAcceleration();
            known = shared_.prototypes.emplace(op.entity, static_cast<int32_t>(scene_.prototypes.size())).first;
            scene_.prototypes.push_back(std::move(prototype));
        }
        const RenderScene& prototype = *scene_.prototypes[static_cast<size_t>(known->second)];
        const bool bounded = prototype.unbounded.empty() && prototype.planes.empty();
        if (bounded && prototype.bounds.empty()) return true; // nothing to draw
        const int32_t transform = addTransform(op);
        objects_.push_back(RenderScene::instanceObject(static_cast<int32_t>(scene_.instances.size())));
        scene_.instances.push_back({known->second, transform, op.material >= 0 ? op.material : defaultMaterial_});
        markHidden(scene_.hiddenInstances, scene_.instances.size(), op.hidden);
        instanceBounds_.push_back(bounded ? worldBounds(prototype.bounds, transform) : Bounds3::everything());
        return true;
    }

    /// Records the hidden bits of the last of `count` primitives or instances: the list stays
    /// empty until one is hidden from something, and then holds one entry for each.
    static void markHidden(std::vector<uint8_t>& hidden, size_t count, unsigned bits) {
        if (bits == 0 && hidden.empty()) return;
        hidden.resize(count - 1, 0);
        hidden.push_back(static_cast<uint8_t>(bits));
    }

    /// The operand's transform: -1 for none, a moving one from kFirstMovingTransform on.
    int32_t addTransform(const Operand& op) {
        if (!op.motion) return addTransform(op.transform);
        std::vector<MovingTransform>& moving = scene_.movingTransforms;
        if (moving.empty() || moving.back().chain != op.motion) moving.push_back({op.transform, op.motion});
        return RenderScene::kFirstMovingTransform + static_cast<int32_t>(moving.size() - 1);
    }

    int32_t addTransform(const Transform& toWorld) {
        if (toWorld.isIdentity()) return -1;
        if (!scene_.transforms.empty()) {
            const Transform& last = scene_.transforms.back().toWorld;
            if (last.linear() == toWorld.linear() && last.offset() == toWorld.offset())
                return static_cast<int32_t>(scene_.transforms.size() - 1);
        }
        scene_.transforms.push_back({toWorld, toWorld.inverse()});
        return static_cast<int32_t>(scene_.transforms.size() - 1);
    }

    /// Sets error_ to `message` as an error at the operand's entity, where its place in the
    /// source is known.
    void failAt(const Operand& op, std::string message) {
        const std::string where = scene::spanLocation(desc_, desc_.entities[op.entity].source);
        error_ = where.empty() ? std::move(message) : where + ": error: " + message;
    }

    /// The heights of the field, read once however often it is drawn; null (with error_ set)
    /// when they cannot be read.
    std::shared_ptr<const HeightGrid> heightGrid(const scene::HeightFieldShape& field, const Operand& op) {
        auto known = shared_.heightGrids.find(field.desc.get());
        if (known != shared_.heightGrids.end()) return known->second;
        std::shared_ptr<const HeightGrid> grid = readHeightGrid(*field.desc, desc_.limits, error_);
        if (!grid) {
            failAt(op, error_);
            return nullptr;
        }
        shared_.heightGrids.emplace(field.desc.get(), grid);
        return grid;
    }

    int32_t addPrimitive(const Operand& op) {
        std::optional<Geometry> geometry = geometryOf(op);
        if (!geometry) return -1; // nothing to draw, or error_ says why
        scene_.primitives.push_back(
            {std::move(*geometry), addTransform(op), materialOf(op)});
        scene_.primitiveEntities.push_back(op.entity);
        markHidden(scene_.hiddenPrimitives, scene_.primitives.size(), op.hidden | desc_.entities[op.entity].hidden);
        return static_cast<int32_t>(scene_.primitives.size() - 1);
    }

    std::optional<Geometry> geometryOf(const Operand& op) {
        const scene::Shape& shape = desc_.entities[op.entity].shape;
        if (auto* field = std::get_if<scene::HeightFieldShape>(&shape)) {
            std::shared_ptr<const HeightGrid> heights = heightGrid(*field, op);
            if (!heights) return std::nullopt;
            return HeightFieldGeometry(std::move(heights), field->desc->smooth);
        }
        if (auto* mesh = std::get_if<scene::MeshShape>(&shape)) {
            std::shared_ptr<const TriangleMesh> triangles = triangleMesh(*mesh, op);
            if (!triangles) return std::nullopt;
            return MeshGeometry(std::move(triangles));
        }
        return makeGeometry(shape, desc_.limits);
    }

    /// The mesh's triangles under their BVH, read and built once however often it is drawn;
    /// null (with error_ set) when it cannot be read or its triangles would pass the primitive
    /// limit.
    std::shared_ptr<const TriangleMesh> triangleMesh(const scene::MeshShape& mesh, const Operand& op) {
        std::shared_ptr<const MeshData> data = meshData(mesh);
        if (!data) return nullptr;
        auto built = shared_.triangleMeshes.find(data.get());
        if (built != shared_.triangleMeshes.end()) return built->second;
        // The description counts each drawing of a mesh as one primitive; its triangles,
        // stored once, count once, here where they are known.
        const size_t triangles = data->triangles.size();
        const uint64_t limit = desc_.limits.maxPrimitives;
        shared_.storedPrimitives = scene::saturatingAdd(shared_.storedPrimitives, triangles);
        if (shared_.storedPrimitives > limit) {
            failAt(op, fmt::format("the scene stores more than {} primitives with the {} triangles of {}; "
                                   "raise the limit with --max-primitives",
                                   limit, triangles,
                                   mesh.written >= 0 ? "a Mesh" : scene::fileToOpen(mesh.resolvedFile, mesh.file)));
            return nullptr;
        }
        auto made = std::make_shared<const TriangleMesh>(data, threads_);
        shared_.triangleMeshes.emplace(data.get(), made);
        root_.meshes.push_back(made);
        return made;
    }

    /// The mesh's data: the front end's, or read here for a description built otherwise.
    std::shared_ptr<const MeshData> meshData(const scene::MeshShape& mesh) {
        if (mesh.written >= 0) return desc_.writtenMeshes[static_cast<size_t>(mesh.written)];
        const std::string& path = scene::fileToOpen(mesh.resolvedFile, mesh.file);
        const auto& known = desc_.meshes.contains(path) ? desc_.meshes : shared_.meshes;
        auto cached = known.find(path);
        if (cached != known.end()) return cached->second;
        std::optional<MeshData> read = scene::readMeshFile(path, scene::kDefaultMaxMeshSize, error_);
        if (!read) return nullptr;
        return shared_.meshes.emplace(path, std::make_shared<const MeshData>(std::move(*read))).first->second;
    }

    /// The operands of a chain of one associative operator, through transforms and groups.
    void collectChain(const Operand& start, scene::CsgOp op, std::vector<Operand>& operands) {
        std::vector<Operand> pending{start};
        while (!pending.empty()) {
            Operand o = std::move(pending.back());
            pending.pop_back();
            const scene::EntityDesc& e = desc_.entities[o.entity];
            if (auto* t = std::get_if<scene::TransformNode>(&e.shape)) {
                pending.push_back(below(o, e, *t));
            } else if (auto* g = std::get_if<scene::GroupNode>(&e.shape);
                       g && (op == scene::CsgOp::Union || op == scene::CsgOp::Merge)) {
                for (int32_t m : g->members) pending.push_back(o.part(e, m));
            } else if (auto* c = std::get_if<scene::CsgNode>(&e.shape); c && c->op == op) {
                pending.push_back(o.part(e, c->right));
                pending.push_back(o.part(e, c->left));
            } else {
                operands.push_back(std::move(o));
            }
        }
    }

    /// Adds a CSG tree; chains are rebalanced ((a − b) − c = a − (b ∪ c), unions and
    /// intersections regrouped by position) so evaluation depth grows like log n.
    int32_t addCsg(const Operand& operand) {
        const scene::EntityDesc& e = desc_.entities[operand.entity];
        if (auto* t = std::get_if<scene::TransformNode>(&e.shape))
            return addCsg(below(operand, e, *t));
        if (auto* inverse = std::get_if<scene::InverseNode>(&e.shape)) {
            CsgTreeNode node;
            node.kind = CsgNodeKind::Inverse;
            node.left = addCsg(operand.part(e, inverse->child));
            node.bounds = Bounds3::everything();
            scene_.csgNodes.push_back(node);
            return static_cast<int32_t>(scene_.csgNodes.size() - 1);
        }
        const scene::CsgNode* c = std::get_if<scene::CsgNode>(&e.shape);
        if (!c && !std::holds_alternative<scene::GroupNode>(e.shape)) {
            int32_t p = addPrimitive(operand);
            if (p < 0) return -1;
            CsgTreeNode leaf;
            leaf.primitive = p;
            leaf.bounds = worldBounds(scene_.primitives[p]);
            leaf.testBounds = leaf.bounds.finite() && !hasCheapCrossings(scene_.primitives[p].geometry);
            leaf.convex = isBoundedConvex(scene_.primitives[p].geometry);
            scene_.csgNodes.push_back(leaf);
            return static_cast<int32_t>(scene_.csgNodes.size() - 1);
        }
        if (c && c->op == scene::CsgOp::Clip)
            return combine(CsgNodeKind::Clip, addCsg(operand.part(e, c->left)), addCsg(operand.part(e, c->right)));
        if (c && c->op == scene::CsgOp::Difference) {
            // Walk the left spine: ((a − b) − c) − d = a − (b ∪ c ∪ d).
            std::vector<Operand> subtracted;
            Operand base = operand;
            while (true) {
                const scene::EntityDesc& be = desc_.entities[base.entity];
                if (auto* t = std::get_if<scene::TransformNode>(&be.shape)) {
                    base = below(base, be, *t);
                } else if (auto* d = std::get_if<scene::CsgNode>(&be.shape); d && d->op == scene::CsgOp::Difference) {
                    collectChain(base.part(be, d->right), scene::CsgOp::Union, subtracted);
                    base = base.part(be, d->left);
                } else {
                    break;
                }
            }
            int32_t left = addCsg(base);
            int32_t right = addBalanced(subtracted, CsgNodeKind::Union);
            return combine(CsgNodeKind::Difference, left, right);
        }
        std::vector<Operand> operands;
        scene::CsgOp op = c ? c->op : scene::CsgOp::Union;
        collectChain(operand, op, operands);
        return addBalanced(operands, op == scene::CsgOp::Intersection ? CsgNodeKind::Intersection
                                     : op == scene::CsgOp::Merge      ? CsgNodeKind::Merge
                                                                      : CsgNodeKind::Union);
    }

    int32_t addBalanced(std::vector<Operand>& operands, CsgNodeKind kind) {
        std::vector<int32_t> nodes;
        for (const Operand& o : operands) {
            int32_t n = addCsg(o);
            if (n >= 0) nodes.push_back(n);
        }
        return balance(nodes, 0, nodes.size(), kind);
    }

    /// Splits by position along the widest axis, so bounds of subtrees are tight.
    int32_t balance(std::vector<int32_t>& nodes, size_t begin, size_t end, CsgNodeKind kind) {
        if (begin == end) return -1;
        if (end - begin == 1) return nodes[begin];
        Bounds3 centroids;
        for (size_t i = begin; i < end; ++i)
            if (scene_.csgNodes[nodes[i]].bounds.finite()) centroids.include(scene_.csgNodes[nodes[i]].bounds.centroid());
        int axis = 0;
        if (!centroids.empty()) {
            Vec3 extent = centroids.extent();
            axis = extent.y > extent.x ? 1 : 0;
            if (extent.z > extent[axis]) axis = 2;
        }
        size_t mid = begin + (end - begin) / 2;
        std::nth_element(nodes.begin() + begin, nodes.begin() + mid, nodes.begin() + end, [&](int32_t a, int32_t b) {
            return key(a, axis) < key(b, axis);
        });
        int32_t left = balance(nodes, begin, mid, kind);
        int32_t right = balance(nodes, mid, end, kind);
        return combine(kind, left, right);
    }

    double key(int32_t node, int axis) const {
        const Bounds3& b = scene_.csgNodes[node].bounds;
        return b.finite() ? b.centroid()[axis] : kInfinity;
    }

    int32_t combine(CsgNodeKind kind, int32_t left, int32_t right) {
        const bool joins = kind == CsgNodeKind::Union || kind == CsgNodeKind::Merge;
        if (left < 0) return joins ? right : -1;
        if (right < 0) return kind == CsgNodeKind::Intersection || kind == CsgNodeKind::Clip ? -1 : left;
        CsgTreeNode node;
        node.kind = kind;
        node.left = left;
        node.right = right;
        const Bounds3& a = scene_.csgNodes[left].bounds;
        const Bounds3& b = scene_.csgNodes[right].bounds;
        if (joins)
            node.bounds = unionOf(a, b);
        else if (kind == CsgNodeKind::Difference) node.bounds = a;
        else node.bounds = {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
        node.testBounds = kind != CsgNodeKind::Difference && node.bounds.finite();
        node.convex = kind == CsgNodeKind::Intersection && scene_.csgNodes[left].convex && scene_.csgNodes[right].convex;
        scene_.csgNodes.push_back(node);
        return static_cast<int32_t>(scene_.csgNodes.size() - 1);
    }

    Bounds3 worldBounds(const Primitive& p) const { return worldBounds(geometryBounds(p.geometry), p.transform); }

    Bounds3 worldBounds(const Bounds3& local, int32_t transform) const {
        if (transform < 0 || !local.finite()) return transform < 0 ? local : Bounds3::everything();
        if (transform >= RenderScene::kFirstMovingTransform)
            return sweptBounds(local, sweep(transform - RenderScene::kFirstMovingTransform));
        return worldBounds(local, scene_.transforms[static_cast<size_t>(transform)].toWorld);
    }

    static Vec3 corner(const Bounds3& b, int i) {
        return {(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
    }

    static Bounds3 worldBounds(const Bounds3& local, const Transform& toWorld) {
        Bounds3 world;
        for (int i = 0; i < 8; ++i) world.include(toWorld.point(corner(local, i)));
        // Rounding of the transformed corners must not cut off a grazing hit.
        Vec3 pad = errorGamma(4) * glm::max(absolute(world.lo), absolute(world.hi));
        return {world.lo - pad, world.hi + pad};
    }

    /// Moving transform `index` at evenly spaced times across the shutter, computed once
    /// however many primitives it moves.
    const std::vector<Transform>& sweep(int32_t index) const {
        if (sweeps_.size() <= static_cast<size_t>(index)) sweeps_.resize(static_cast<size_t>(index) + 1);
        std::vector<Transform>& samples = sweeps_[static_cast<size_t>(index)];
        if (samples.empty()) {
            const MovingTransform& moving = scene_.movingTransforms[static_cast<size_t>(index)];
            const int count = 8 * static_cast<int>(moving.chain->size());
            for (int s = 0; s <= count; ++s) samples.push_back(moving.at(static_cast<double>(s) / count).toWorld);
        }
        return samples;
    }

    /// Bounds of everything the box is while the shutter is open: its bounds at the sweep's
    /// times, grown by the most a corner moves from one to the next, as a corner's path between
    /// two of them (an arc, where it turns) strays from their chord by less than that.
    static Bounds3 sweptBounds(const Bounds3& local, const std::vector<Transform>& sweep) {
        Bounds3 swept;
        double stride = 0;
        for (size_t s = 0; s < sweep.size(); ++s) {
            swept = unionOf(swept, worldBounds(local, sweep[s]));
            if (s == 0) continue;
            for (int i = 0; i < 8; ++i)
                stride = std::max(stride, glm::length(sweep[s].point(corner(local, i)) - sweep[s - 1].point(corner(local, i))));
        }
        return {swept.lo - Vec3(stride), swept.hi + Vec3(stride)};
    }

    Bounds3 objectBounds(int32_t object) const {
        if (RenderScene::isPrimitiveObject(object)) return worldBounds(scene_.primitives[object]);
        if (RenderScene::isInstanceObject(object))
            return instanceBounds_[static_cast<size_t>(RenderScene::instanceOfObject(object))];
        return scene_.csgNodes[RenderScene::csgNodeOfObject(object)].bounds;
    }

    /// Keeps a plain plane in the inline-tested list; false for anything else.
    bool addPlane(int32_t object) {
        if (!RenderScene::isPrimitiveObject(object)) return false;
        const Primitive& p = scene_.primitives[object];
        const PlaneGeometry* plane = shapeIf<PlaneGeometry>(p.geometry);
        if (!plane) return false;
        if (plane->empty()) return true; // a zero normal: nothing to draw
        if (p.transform >= RenderScene::kFirstMovingTransform) return false; // tested as it is at the ray's time
        Vec3 normal = plane->normal(), point = plane->position();
        if (p.transform >= 0) {
            const Transform& t = scene_.transforms[p.transform].toWorld;
            normal = t.normal(normal);
            point = t.point(point);
        }
        scene_.planes.push_back({normal, glm::dot(normal, point), object});
        return true;
    }

    void finishAcceleration() {
        std::vector<int32_t> bounded;
        bounded.reserve(objects_.size());
        for (int32_t object : objects_) {
            Bounds3 b = objectBounds(object);
            if (b.empty()) continue; // an intersection of disjoint solids
            if (!b.finite()) {
                if (!addPlane(object)) scene_.unbounded.push_back(object);
                continue;
            }
            bounded.push_back(object);
            scene_.bounds.include(b);
        }
        std::vector<int32_t>().swap(objects_);
        // The bounds are asked for again rather than held: for a million primitives they would
        // take 48 MB. The build asks from several threads, which is safe now that the pass
        // above has swept every moving transform (sweep() fills its cache only once).
        const size_t count = bounded.size();
        scene_.bvh.build(count, [&](size_t i) { return objectBounds(bounded[i]); }, threads_, bounded);
    }

    /// What the builders of a scene and of its prototypes share: files read once, meshes
    /// built once, the count against the primitive limit, and what is instanced.
    struct Shared {
        std::map<std::string, std::shared_ptr<const MeshData>> meshes;
        std::map<const MeshData*, std::shared_ptr<const TriangleMesh>> triangleMeshes;
        std::map<const scene::HeightFieldDesc*, std::shared_ptr<const HeightGrid>> heightGrids;
        /// The primitives drawn and the triangles of the meshes built so far.
        uint64_t storedPrimitives = 0;
        std::shared_ptr<const scene::SceneStorage> storage; ///< what is instanced
        std::map<int32_t, int32_t> prototypes; ///< entity -> its prototype
    };

    const scene::SceneDesc& desc_;
    RenderScene& scene_;
    RenderScene& root_; ///< the scene whose prototype this builds, or scene_ itself
    unsigned threads_;
    std::string& error_;
    Shared ownShared_;
    Shared& shared_;
    int32_t defaultMaterial_ = 0;
    bool instancing_ = true;
    std::vector<Bounds3> instanceBounds_; ///< of each instance, in world space
    mutable std::vector<std::vector<Transform>> sweeps_; ///< by moving transform (sweep())
    /// What the acceleration structure is to hold: primitives, CSG roots (RenderScene::csgObject)
    /// and instances (RenderScene::instanceObject).
    std::vector<int32_t> objects_;
};

std::unique_ptr<RenderScene> buildRenderScene(const scene::SceneDesc& desc, std::string& error,
                                              unsigned threads) {
    auto scene = std::make_unique<RenderScene>();
    RenderSceneBuilder builder(desc, *scene, threads, error);
    if (!builder.build()) return nullptr;
    return scene;
}

} // namespace crt::tracer
