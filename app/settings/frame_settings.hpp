#pragma once
// The frame's choices as typed values, grouped by the module that reads them. Passes and techniques
// receive these structs, never strings; the only place that turns text into them is settings.cpp,
// whose declaration table also holds every default (so there are none here).
#include <cstdint>

namespace ppr::app {

enum class PprFallback : uint32_t { Ssr, None, SsrHoles };
enum class NormalMap : uint32_t { Off, Approx, Raymarch };
// normalmap=raymarch's search for where the mapped ray meets what it reflects: none (the slides' taps),
// the surfaces' planes (then the taps), or the walk and bisection from the taken tap.
enum class NormalRefine : uint32_t { Off, Planes, Walk };
enum class EnvSource : uint32_t { Sky, Probe };
// PPR hole filling: none, the depth-aware rule (passes/ppr_common/ppr_resolve.glsl), or the slides' rule.
enum class HoleRule : uint32_t { Off, Enclosed, Slides };
// How passes clear images (passes/common/clear_pass.hpp); auto: compute unless the device is a CPU.
enum class ClearMethod : uint32_t { Auto, Transfer, Compute };
// The G-buffer's depth pre-pass; auto: while the scene's triangles are few for the frame's pixels (frame/depth_prepass.hpp).
enum class DepthPrepass : uint32_t { Off, On, Auto };

struct ViewSettings {        // owner: frame (composite, lighting, tonemap, shadow map)
    uint32_t debug;          // gpu::kDebug* (settings/debug_views.hpp)
    float exposure;
    uint32_t shadowRes;
    bool shadowCache;        // draw the shadow map again only when what casts it changes (frame/shadow_map_cache.hpp)
    ClearMethod clear;
    DepthPrepass depthPrepass;
};
struct EnvSettings {         // owner: env (every technique's misses)
    bool fallback;           // misses and screen edges fall back to the environment
    EnvSource source;        // what the environment is: the sky, or the reflection probe (app/frame/environment_probe.hpp)
};
struct TileSettings {        // owner: tiles (tile classification, used by ppr and the ssr-* techniques)
    bool indirect;           // dispatch over the tile lists (false: whole screen)
    uint32_t classifyThreads; // tile classification's invocations per tile (passes/tile_classify/classify_threads.hpp); 0: auto
};
struct PprSettings {         // owner: ppr
    HoleRule holes;
    bool filter, antibleed;
    bool tiles;              // per-tile reflector culling in the projection
    bool facing;             // project only surfaces that face the mirrored eye
    bool splat;              // magnified surfaces fill the cells between their pixels' landings
    uint32_t projectThreads; // the projection's invocations per tile (passes/ppr_project/project_threads.hpp); 0: auto
    uint32_t reachThreads;   // the reach pass's invocations per tile (passes/ppr_reach/reach_threads.hpp); 0: auto
    PprFallback fallback;
    NormalMap normalMap;     // the bonus slides' normal-map approximation in the reflection pass
    NormalRefine normalRefine;  // raymarch: find where the ray meets what it reflects
    bool contact;            // holes=1: march toward the reflected point for what the main view hides
};
struct SsrSettings {         // owner: ssr (the four ssr-* techniques and PPR's fallback)
    float distance, thickness, thicknessScale;
    uint32_t steps;
    uint32_t hizThreads;     // the depth hierarchy build's invocations per cell (passes/hiz/hiz_threads.hpp); 0: auto
    bool hizSkip;            // ssr-hiz's march crosses an 8x8 cell it stays behind in one step
};
struct GlassSettings {       // owner: glass (PPR's glass atlas and the planar reference's)
    bool enabled;
    uint32_t atlas;          // texels per side
};

// How the ray-traced reference decides a flat mirror pixel at a silhouette (passes/raytrace/raster_coverage.glsl).
enum class RtCoverage : uint32_t { Exact, Raster };
struct RaytraceSettings {    // owner: raytraced (the ray-traced reference)
    RtCoverage coverage;     // exact: the triangle the ray meets; raster: as the planar reference's rasterizer snaps it
};

enum class Reproject : uint32_t { Surface, Candidates, Virtual };  // values = taa.h kReproject*

struct TaaSettings {         // owner: taa (passes/taa)
    bool enabled;            // jitter + temporal resolve of the HDR frame (off while a debug view is shown)
    Reproject reproject;     // how the reflection's own history is fetched
    bool split;              // the frame's history holds the surface part; the resolved reflection is added after
    bool average;            // histories count their frames: equal shares after a reset; a still pixel keeps the jitter cycle's mean
    bool motionCap;          // with average: the frame's history keeps less of itself where it was fetched between texels
    bool reflectionCap;      // with average: the same cap on the reflection's own history (off by default: docs/temporal.md)
    bool rimKeep;            // with average: a moving pixel the jitter takes off a reflector keeps its reflection's history
    bool stillSpread;        // with average: a still pixel's own spread over its run, not only the 3×3 box, decides a clip
    bool stillRange;         // with stillSpread: that spread is the run's luma range (else its moments)
    bool stillKeep;          // with average: a still pixel's reflection history is never rejected by its path's depth
    bool movingEdge;         // virtual: a rejected history beside a slow moving draw's reflection restarts from the mean
    bool movingFilter;       // a moving draw's pixels blend the current frame filtered to their centre, not its jittered sample
    uint32_t threads;        // both resolves' invocations per 16x16 tile (passes/taa/taa_threads.hpp); 0: auto
};

struct FrameSettings {
    ViewSettings view;
    TileSettings tiles;
    PprSettings ppr;
    SsrSettings ssr;
    GlassSettings glass;
    EnvSettings env;
    RaytraceSettings raytrace;
    TaaSettings taa;
};

}  // namespace ppr::app
