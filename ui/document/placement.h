// Where new things go: on the surface a view ray meets (under the viewport centre or the
// cursor), else a sensible distance along it; resting on that surface or on the floor below;
// and the scale that makes an imported mesh fit the view.
#pragma once

#include "scene/document.h"

namespace rs {
class CompiledScene;
}

namespace rs::ui {

/// Where a view ray puts a new object.
struct Placement {
    Vec3 point{0.0f};   ///< The surface point hit, else a point `fallbackDistance` along the ray.
    Vec3 normal{0.0f};  ///< The hit surface's normal on the viewer's side; -direction when none.
    Vec3 viewDir{0.0f, 0.0f, -1.0f};  ///< Unit direction of the ray.
    float distance = 0.0f;            ///< From the ray's origin to `point`.
    bool onSurface = false;
};

/// Casts `ray` into `scene` (nullptr: nothing to hit); without a hit the point lies
/// `fallbackDistance` along the ray.
Placement placeAlong(const CompiledScene* scene, const Ray& ray, float fallbackDistance);

/// The distance in front of `view` a new object goes when no surface is there: its target's,
/// at most `kMaxFallbackDistance` (a view backed far out must not put it out of sight).
float fallbackDistance(const Camera& view);
inline constexpr float kMaxFallbackDistance = 5.0f;

/// Moves object or light `id` to `at`: an object so that it touches the surface from the
/// normal's side (its bounds' centre `at.normal` times its half depth off the point), a
/// light a little short of the surface towards the viewer, a plane through the point.
void restOn(SceneDocument& doc, ObjectId id, const Placement& at);

/// Drops object `id` along -`up` (unit) until its bounds rest on the first surface of
/// `scene` below their centre; false (unchanged) when nothing is below or `id` is unbounded.
bool snapToFloor(SceneDocument& doc, ObjectId id, const CompiledScene* scene, const Vec3& up);

/// The uniform scale that fits a mesh of object-space `bounds`, seen through `view` from
/// `distance`, into the view: 1 when its size is already between kMinViewShare and
/// kMaxViewShare of the visible height there, else the factor (two significant digits) that
/// makes it kFitViewShare of it, within the range Transform -> Scale accepts.
float fitScale(const Aabb& bounds, const Camera& view, float distance);
inline constexpr float kMinViewShare = 0.02f;
inline constexpr float kMaxViewShare = 1.0f;
inline constexpr float kFitViewShare = 0.5f;

/// Places new object or light `id` (in `doc`, not yet in `scene`) as a Blender user expects
/// when no place was pointed at: in front of `view` at a comfortable distance (half the way
/// to the surface ahead, at most fallbackDistance()), and
/// - an object rests on the surface below that point (the floor), moved sideways across the
///   view, a little further each try (then further out), until its bounds clear every other
///   object's where it can be seen: in the frame, its centre not behind a surface;
/// - a plane becomes a floor under the scene: facing up, through the lowest point of the
///   objects' bounds (through that surface below, when there are none);
/// - a light hangs above that point, a third of the way to the ceiling (or of the distance
///   when nothing is above).
/// `up` is the scene's up (unit), `aspect` the view's width over its height. Returns the point the
/// object rests on (a light's is the one below it), which a spot is aimed at.
Vec3 placeInView(SceneDocument& doc, ObjectId id, const CompiledScene* scene, const Camera& view,
                 const Vec3& up, float aspect);
/// Tries across the view before a new object is left overlapping another.
inline constexpr int kPlacementTries = 12;

/// Gives each sun light read from a file a place to draw its glyph: a sun has no position
/// (the file has none for it, so it reads as the origin, often inside the scene or out of
/// view), so its glyph goes upstream of the scene, against its direction from the centre
/// of the objects' bounds by their radius plus one unit, where the light comes from. Suns
/// with a position other than the origin (placed in this run of the designer) keep it.
void anchorSunGlyphs(SceneDocument& doc);

}  // namespace rs::ui
