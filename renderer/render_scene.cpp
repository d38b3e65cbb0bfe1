#include "renderer/render_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "base/errors/input_error.h"
#include "base/image/image_io.h"
#include "base/scene/scene_features.h"
#include "renderer/nearest_hit.h"
#include "renderer/render_plan.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

// Builds and places the instances: one per transform that spheres or triangles are written
// under, holding all of them (a cube of twelve `tri` under one `translate` is one instance), and
// one per mesh instance, sharing its definition's geometry. Spheres and triangles without a
// transform go to the world's list.
class InstanceGatherer {
  public:
    InstanceGatherer(const Scene& scene, RenderScene& render_scene)
        : scene_(scene), render_(render_scene) {}

    void gather() {
        PrimitiveList& world = render_.primitives;
        gather_kind(scene_.spheres, &PrimitiveList::spheres, &InstanceGeometry::sphere_ids,
                    render_.sphere_instance, render_.sphere_index);
        gather_kind(scene_.triangles, &PrimitiveList::triangles, &InstanceGeometry::triangle_ids,
                    render_.triangle_instance, render_.triangle_index);
        gather_mesh_instances();
        for (InstanceGeometry& geometry : render_.instance_geometries)
            finish_geometry(geometry);
        for (Instance& instance : render_.instances)
            place_instance(instance, render_.instance_geometries[instance.geometry]);
        world.planes.reserve(scene_.planes.size());
        for (const ScenePlane& p : scene_.planes) {
            if (p.attributes.transform == 0) {
                world.planes.push_back(p.shape);
                continue;
            }
            const Transform& m = transform_of(p.attributes.transform);
            world.planes.push_back(
                {point_to_world(m, p.shape.point), normal_to_world(m, p.shape.normal)});
        }
    }

  private:
    // The objects of one kind, in Scene order: each without a transform to the world's list (and
    // its number to `world_index`), each under one to the instance of its transform (and its
    // number to that geometry's `ids`); `instance_of` gets each one's instance, or kNoInstance.
    template <class Object, class Shape>
    void gather_kind(const std::vector<Object>& objects, std::vector<Shape> PrimitiveList::*shapes,
                     std::vector<std::size_t> InstanceGeometry::*ids,
                     std::vector<std::uint32_t>& instance_of,
                     std::vector<std::size_t>& world_index) {
        for (std::size_t k = 0; k < objects.size(); ++k) {
            const Object& object = objects[k];
            if (object.attributes.transform == 0) {
                instance_of.push_back(kNoInstance);
                world_index.push_back(k);
                (render_.primitives.*shapes).push_back(object.shape);
                continue;
            }
            const std::uint32_t instance = group_of(object.attributes.transform);
            instance_of.push_back(instance);
            InstanceGeometry& geometry = geometry_of(instance);
            (geometry.primitives.*shapes).push_back(object.shape);
            (geometry.*ids).push_back(k);
        }
    }

    // The transform of a node, composed by stage 5 the first time an object under it is met.
    const Transform& transform_of(std::uint32_t node) {
        auto found = transforms_.find(node);
        if (found == transforms_.end()) {
            found = transforms_.emplace(node, compose(transform_ops(scene_, node))).first;
        }
        return found->second;
    }

    std::uint32_t group_of(std::uint32_t node) {
        const auto found = groups_.find(node);
        if (found != groups_.end()) return found->second;
        const auto instance = static_cast<std::uint32_t>(render_.instances.size());
        Instance placed;
        placed.geometry = render_.instance_geometries.size();
        placed.transform = transform_of(node);
        render_.instance_geometries.emplace_back();
        render_.instances.push_back(placed);
        groups_.emplace(node, instance);
        return instance;
    }

    InstanceGeometry& geometry_of(std::uint32_t instance) {
        return render_.instance_geometries[render_.instances[instance].geometry];
    }

    // Every instance of a definition points at one geometry, built the first time it is placed.
    void gather_mesh_instances() {
        render_.first_mesh_instance = render_.instances.size();
        std::unordered_map<std::uint32_t, std::size_t> geometry_of_definition;
        std::size_t first_triangle = scene_.triangles.size();
        for (const MeshInstance& mesh : scene_.mesh_instances) {
            auto found = geometry_of_definition.find(mesh.definition);
            if (found == geometry_of_definition.end()) {
                InstanceGeometry geometry;
                geometry.primitives.triangles = scene_.mesh_definitions[mesh.definition].triangles;
                render_.instance_geometries.push_back(std::move(geometry));
                found = geometry_of_definition
                            .emplace(mesh.definition, render_.instance_geometries.size() - 1)
                            .first;
            }
            Instance placed;
            placed.geometry = found->second;
            if (mesh.attributes.transform != 0) {
                placed.transform = transform_of(mesh.attributes.transform);
            }
            placed.first_triangle = first_triangle;
            first_triangle += scene_.mesh_definitions[mesh.definition].triangles.size();
            render_.instances.push_back(placed);
        }
    }

    const Scene& scene_;
    RenderScene& render_;
    std::unordered_map<std::uint32_t, Transform> transforms_;
    std::unordered_map<std::uint32_t, std::uint32_t> groups_;
};

// Each instance in turn, below kBvhFromPrimitives instances.
std::optional<PrimitiveHit> instances_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                                  std::optional<PrimitiveHit> best,
                                                  TraversalStats* stats) {
    if (render_scene.instance_bvh) {
        keep_nearer(best, render_scene.instance_bvh->closest_hit(render_scene.instances,
                                                                 render_scene.instance_geometries,
                                                                 cut_at(ray, best), stats));
        return best;
    }
    for (const Instance& instance : render_scene.instances) {
        keep_nearer(best, instance_closest_hit(instance,
                                               render_scene.instance_geometries[instance.geometry],
                                               cut_at(ray, best), stats));
    }
    return best;
}

// The mesh instance (its number in Scene::mesh_instances) that holds triangle `index` of the
// scene's numbering, one past Scene::triangles.
std::size_t mesh_instance_at(const RenderScene& render_scene, std::size_t index) {
    const auto first = render_scene.instances.begin() +
                       static_cast<std::ptrdiff_t>(render_scene.first_mesh_instance);
    const auto after = std::upper_bound(first, render_scene.instances.end(), index,
                                        [](std::size_t wanted, const Instance& instance) {
                                            return wanted < instance.first_triangle;
                                        });
    if (after == first) throw std::out_of_range("no mesh instance holds this triangle");
    return static_cast<std::size_t>(after - first) - 1;
}

}  // namespace

SceneCamera make_scene_camera(const Scene& scene) {
    const CameraSpec& c = scene.camera;
    if (c.ortho) {
        return make_orthographic_camera(c.lookfrom, c.lookat, c.up, c.ortho->left, c.ortho->right,
                                        c.ortho->bottom, c.ortho->top, scene.width, scene.height);
    }
    return make_perspective_camera(c.lookfrom, c.lookat, c.up, c.fovy_degrees, scene.width,
                                   scene.height);
}

RenderScene prepare_render_scene(const Scene& scene) {
    RenderScene render_scene;
    render_scene.scene = &scene;
    for (const SceneTexture& texture : scene.textures) {
        try {
            render_scene.textures.push_back(read_image(texture.path));
        } catch (const std::runtime_error& error) {
            throw InputError(scene.path, static_cast<int>(texture.line),
                             std::string("cannot read the image: ") + error.what());
        }
        // Stage 11's lookups take images of at most a million texels a side, so that their
        // indices fit an int.
        const Image& image = render_scene.textures.back();
        if (image.width() == 0 || image.height() == 0 || image.width() > 1000000 ||
            image.height() > 1000000) {
            throw InputError(scene.path, static_cast<int>(texture.line),
                             "the image is " + std::to_string(image.width()) + " x " +
                                 std::to_string(image.height()) +
                                 ": a texture has 1 to 1,000,000 texels a side");
        }
    }
    render_scene.camera = make_scene_camera(scene);
    InstanceGatherer(scene, render_scene).gather();
    const SceneFeatures features = scene_features(scene);
    if (uses_bvh(features)) {
        render_scene.bvh.emplace(render_scene.primitives, BvhSplit::sah);
        render_scene.planes.planes = render_scene.primitives.planes;
    }
    if (render_scene.instances.size() >= kBvhFromPrimitives) {
        render_scene.instance_bvh.emplace(render_scene.instances);
    }
    render_scene.ray_offset = scene.ray_offset;
    render_scene.refraction = features.uses_refraction();
    // No limit (`maxdepth -1`) is for a path tracer's Russian roulette; these recursions have
    // none, and follow the courses' default depth.
    const int depth = scene.max_depth == kUnboundedDepth ? kDefaultDepth : scene.max_depth;
    render_scene.bounces = features.uses_reflection() || features.uses_refraction() ? depth : 0;
    return render_scene;
}

std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats) {
    const PrimitiveList& list = render_scene.primitives;
    std::optional<PrimitiveHit> best;
    if (render_scene.bvh) {
        best = render_scene.bvh->closest_hit(ray, stats);
    } else {
        best = closest_hit(ray, list);
        if (stats) stats->primitive_tests += list.spheres.size() + list.triangles.size();
    }
    if (best && best->kind == PrimitiveKind::sphere) {
        best->index = render_scene.sphere_index[best->index];
    } else if (best && best->kind == PrimitiveKind::triangle) {
        best->index = render_scene.triangle_index[best->index];
    }
    if (render_scene.bvh) {
        keep_nearer(best, closest_hit(cut_at(ray, best), render_scene.planes));
    }
    if (stats) stats->primitive_tests += list.planes.size();
    return instances_closest_hit(render_scene, ray, best, stats);
}

bool scene_occluded(const RenderScene& render_scene, const Ray& ray) {
    if (render_scene.bvh) {
        if (render_scene.bvh->occluded(ray, nullptr)) return true;
        if (closest_hit(ray, render_scene.planes)) return true;
    } else if (closest_hit(ray, render_scene.primitives)) {
        return true;
    }
    if (render_scene.instance_bvh) {
        return render_scene.instance_bvh->occluded(render_scene.instances,
                                                   render_scene.instance_geometries, ray);
    }
    for (const Instance& instance : render_scene.instances) {
        if (instance_occluded(instance, render_scene.instance_geometries[instance.geometry], ray))
            return true;
    }
    return false;
}

Ray camera_ray(const SceneCamera& camera, int i, int j) {
    if (const auto* perspective = std::get_if<PerspectiveCamera>(&camera)) {
        return perspective_ray(*perspective, i, j);
    }
    return orthographic_ray(std::get<OrthographicCamera>(camera), i, j);
}

Ray camera_ray(const RenderScene& render_scene, int i, int j) {
    Ray ray = camera_ray(render_scene.camera, i, j);
    ray.t_min = std::max(ray.t_min, render_scene.camera_t_min);
    ray.t_max = std::min(ray.t_max, render_scene.camera_t_max);
    return ray;
}

Ray camera_ray_through(const RenderScene& render_scene, const Vec2& film) {
    const auto* perspective = std::get_if<PerspectiveCamera>(&render_scene.camera);
    Ray ray = perspective ? perspective_ray_through(*perspective, film)
                          : orthographic_ray_through(
                                std::get<OrthographicCamera>(render_scene.camera), film);
    ray.t_min = std::max(ray.t_min, render_scene.camera_t_min);
    ray.t_max = std::min(ray.t_max, render_scene.camera_t_max);
    return ray;
}

const ObjectAttributes& attributes_of(const RenderScene& render_scene, PrimitiveKind kind,
                                      std::size_t index) {
    const Scene& scene = *render_scene.scene;
    switch (kind) {
        case PrimitiveKind::sphere:
            return scene.spheres.at(index).attributes;
        case PrimitiveKind::triangle:
            if (index < scene.triangles.size()) return scene.triangles[index].attributes;
            return scene.mesh_instances.at(mesh_instance_at(render_scene, index)).attributes;
        case PrimitiveKind::plane:
            return scene.planes.at(index).attributes;
    }
    throw std::logic_error("attributes_of: unknown primitive kind");
}

const Material& material_of(const RenderScene& render_scene, const PrimitiveHit& hit) {
    return render_scene.scene->materials[attributes_of(render_scene, hit.kind, hit.index).material];
}

const Instance* instance_of(const RenderScene& render_scene, PrimitiveKind kind,
                            std::size_t index) {
    const Scene& scene = *render_scene.scene;
    std::uint32_t instance = kNoInstance;
    if (kind == PrimitiveKind::sphere) {
        instance = render_scene.sphere_instance.at(index);
    } else if (kind == PrimitiveKind::triangle) {
        if (index >= scene.triangles.size()) {
            return &render_scene.instances[render_scene.first_mesh_instance +
                                           mesh_instance_at(render_scene, index)];
        }
        instance = render_scene.triangle_instance[index];
    }
    return instance == kNoInstance ? nullptr : &render_scene.instances[instance];
}

const Triangle& triangle_shape(const RenderScene& render_scene, std::size_t index) {
    const Scene& scene = *render_scene.scene;
    if (index < scene.triangles.size()) return scene.triangles[index].shape;
    const std::size_t mesh = mesh_instance_at(render_scene, index);
    const Instance& instance = render_scene.instances[render_scene.first_mesh_instance + mesh];
    const MeshDefinition& definition =
        scene.mesh_definitions[scene.mesh_instances[mesh].definition];
    return definition.triangles.at(index - instance.first_triangle);
}

TriangleCorners triangle_corners(const RenderScene& render_scene, std::size_t index) {
    const Scene& scene = *render_scene.scene;
    if (index < scene.triangles.size()) {
        return {scene.triangles[index].vertex_normals, scene.triangles[index].vertex_uvs};
    }
    const std::size_t mesh = mesh_instance_at(render_scene, index);
    const Instance& instance = render_scene.instances[render_scene.first_mesh_instance + mesh];
    const MeshDefinition& definition =
        scene.mesh_definitions[scene.mesh_instances[mesh].definition];
    const std::size_t k = index - instance.first_triangle;
    return {definition.vertex_normals.at(k), definition.vertex_uvs.at(k)};
}

const char* kind_name(PrimitiveKind kind) {
    switch (kind) {
        case PrimitiveKind::sphere:
            return "sphere";
        case PrimitiveKind::triangle:
            return "triangle";
        case PrimitiveKind::plane:
            return "plane";
    }
    return "primitive";
}

}  // namespace raystep
