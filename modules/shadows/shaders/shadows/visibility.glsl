// Shadow visibility math, written once in a GLSL subset that also compiles as C++ with GLM
// (modules/shadows/include/shadows/VisibilityMath.h), so the CPU tests run exactly what the shader runs.
// Subset rules: float literals carry an `f` suffix, outputs use GS_OUT(T), no texture access here.
//
// Units: tap offsets and gradients are per shadow-map texel (dz per texel step); depths are in the shadow
// map's [0,1] range. Tap offsets are in the pattern's own frame: a per-pixel rotation is applied only when
// fetching, and a point gradient is rotated into the pattern frame by the caller, so fits stay rotation-free.
// Every division is guarded and every visibility is clamped to [0,1].

const int GS_MAX_TAPS = 64;

float gsSaturate(float x) { return clamp(x, 0.0f, 1.0f); }

// Plain depth test: lit when the receiver is not behind the stored occluder depth.
float gsCompare(float storedDepth, float receiverDepth) { return receiverDepth <= storedDepth ? 1.0f : 0.0f; }

// Bias reference, "Shadows from Front or Back faces": the comparison hardware rounds the reference to the
// depth format; flooring it to a multiple of the format's step first makes that rounding a no-op, so a D16 map
// shows no extra acne. `step` is 1/65535 for D16, 1/16777215 for D24, 0 (no quantisation) for D32F.
float gsFloorToStep(float depth, float step) { return step > 0.0f ? floor(depth / step) * step : depth; }

// Schüler, "Eliminating Surface Acne with Gradient Shadow Mapping" (ShaderX4): the fuzzy comparison
// saturate(diff / |g| + 1). The band width is the gradient magnitude times `fuzzyScale` texels, never below
// `minimumWidth` (the depth format's step), so a zero gradient (surface facing the light) gives a hard but
// finite comparison instead of 0/0.
float gsFuzzyVisibility(float storedDepth, float receiverDepth, float gradientMagnitude, float fuzzyScale,
                        float minimumWidth) {
    float width = max(max(gradientMagnitude * fuzzyScale, minimumWidth), 1e-30f);
    return gsSaturate((storedDepth - receiverDepth) / width + 1.0f);
}

// Normal offset (bias reference, "Alternatives": growing the receiver along its normal), sized so that no
// lookup within `reach` (world units in the map's plane) of the receiver's own sees its surface in front of it.
// On a plane at angle θ to the light (cosθ = `cosine`), a lookup r away meets surface depth r·tanθ nearer to
// the light; a point h above the plane along its normal lies h/cosθ in front of the plane behind it, so
// h = r·sinθ is just enough at any angle, and moves the lookup by only h·sinθ <= r. Facing the light (θ = 0)
// needs no offset; the depth bias covers rounding there.
float gsNormalOffset(float reach, float cosine) {
    float c = clamp(cosine, -1.0f, 1.0f);
    return reach * sqrt(max(1.0f - c * c, 0.0f));
}

// The receiver's own facet, on the side the camera sees: with window x right and y up, dP/dx × dP/dy faces the
// viewer (the derivatives of the interpolated position stay within one triangle). The depths in the map come
// from facets; an interpolated normal bends across creases, and real models' smoothed normals point up to 45°
// and more through their own facets, so biases along them move lookups behind the surface. The derivatives
// are rescaled to a largest component of 1 before the cross product, so that a tiny scene's does not
// underflow; an edge-on facet (no area on screen), and derivatives below the smallest normal float (which GPUs
// may flush to zero, and whose reciprocal overflows), keep `shadingNormal`. One reciprocal and one inverse
// square root rather than nine divisions and a square root.
vec3 gsFacetNormal(vec3 dPdx, vec3 dPdy, vec3 shadingNormal) {
    vec3 magnitude = max(abs(dPdx), abs(dPdy));
    float scale = max(max(magnitude.x, magnitude.y), magnitude.z);
    if (!(scale >= 1.17549435e-38f) || isinf(scale)) {
        return shadingNormal;
    }
    float inverseScale = 1.0f / scale;
    vec3 facet = cross(dPdx * inverseScale, dPdy * inverseScale);
    float area2 = dot(facet, facet);
    return area2 > 1e-24f ? facet * inversesqrt(area2) : shadingNormal;
}

// Adaptive depth bias (Dou, Yan, Kerzner, Dai, Wyman, "Adaptive Depth Bias for Shadow Maps", JCGT 3(4), 2014,
// section 3): the receiver's tangent plane (through `position`, normal `normal`) seen in the shadow map. A
// projective map takes planes to planes, so the plane's map depth is exactly affine in the map's coordinates,
// and its gradient follows from the images of two tangent vectors t under the map's derivative at p:
// (M t).xyz / w - (M p).xyz (M t).w / w². Returns dz per texel; zero where the plane contains the light's rays
// (edge-on, where it has no depth to predict) or the normal is degenerate.
vec2 gsTangentPlaneGradient(mat4 worldToShadow, vec3 position, vec3 normal, float resolution) {
    if (!(dot(normal, normal) > 1e-20f)) {
        return vec2(0.0f);
    }
    vec3 helper = abs(normal.x) < 0.9f * length(normal) ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f);
    vec3 tangent = normalize(cross(normal, helper));
    vec3 bitangent = normalize(cross(normal, tangent));
    vec4 p = worldToShadow * vec4(position, 1.0f);
    float w = abs(p.w) > 1e-20f ? p.w : 1e-20f;
    vec4 a = worldToShadow * vec4(tangent, 0.0f);
    vec4 b = worldToShadow * vec4(bitangent, 0.0f);
    vec3 imageA = (vec3(a) - vec3(p) * (a.w / w)) / w;
    vec3 imageB = (vec3(b) - vec3(p) * (b.w / w)) / w;
    vec3 texels = vec3(resolution, resolution, 1.0f);
    vec3 n = cross(imageA * texels, imageB * texels);
    if (!(abs(n.z) > 1e-6f * length(n))) {
        return vec2(0.0f);
    }
    return vec2(-n.x / n.z, -n.y / n.z);
}

// Receiver plane depth bias (bias reference, "Receiver Plane Depth Bias"): dz/duv from screen derivatives by the
// chain rule, inverting the 2x2 Jacobian d(uv)/d(xy). Returns zero where the Jacobian is (nearly) singular —
// the receiver is seen edge-on or the pixel quad straddles a discontinuity — rather than an unbounded slope.
vec2 gsReceiverPlaneGradient(vec2 duvdx, vec2 duvdy, float dzdx, float dzdy) {
    float det = duvdx.x * duvdy.y - duvdx.y * duvdy.x;
    float scale = abs(duvdx.x * duvdy.y) + abs(duvdx.y * duvdy.x);
    if (!(abs(det) > 1e-6f * scale) || !(scale > 0.0f)) {
        return vec2(0.0f);
    }
    return vec2(duvdy.y * dzdx - duvdx.y * dzdy, duvdx.x * dzdy - duvdy.x * dzdx) / det;
}

// A tap's predicted depth change from the fragment, kept from going deeper: only what lies nearer the light
// than the fragment can occlude it (the bias reference's min(0, bias) clamp, "Applications"). Downhill
// predictions add nothing but risk: beyond the receiver's own silhouette in the map (a convex limb) a steep
// gradient extrapolates past the background behind it, which then looks like an occluder.
float gsNoDeeperThanFragment(float rise) {
    return min(rise, 0.0f);
}

// Average gradient by least squares over the taps' own depths (GSM multisampling reference, "Optimizing Texture
// Look-ups"): g = (sum o o^T)^-1 sum (d - mean d) o. `inverseCovariance` is precomputed per tap pattern (zero
// when the pattern is degenerate, which yields a zero gradient). One pass: the sums run on depths shifted by the
// first tap's (exact for the mean-free form, and no cancellation between depths near 1).
vec2 gsLeastSquaresGradient(const float depths[GS_MAX_TAPS], const vec2 offsets[GS_MAX_TAPS], int count,
                            mat2 inverseCovariance) {
    float shift = depths[0];
    float sum = 0.0f;
    vec2 weighted = vec2(0.0f);
    vec2 offsetSum = vec2(0.0f);
    for (int i = 0; i < count; ++i) {
        float d = depths[i] - shift;
        sum += d;
        weighted += d * offsets[i];
        offsetSum += offsets[i];
    }
    weighted -= (sum / float(max(count, 1))) * offsetSum;
    return inverseCovariance * weighted;
}

// The reference's unrolled circular-8 pattern: axial taps at (±L,0),(0,±L) with L = sqrt(2)·d and diagonal taps at
// (±d,±d). Sum x^2 = 2L^2 + 4d^2 = 8d^2, so g = [sqrt(2)(d1-d0) + d5+d7-d4-d6] / (8d) (x; y alike).
// Tap order: 0 (-L,0), 1 (L,0), 2 (0,-L), 3 (0,L), 4 (-d,-d), 5 (d,-d), 6 (-d,d), 7 (d,d).
vec2 gsCircular8Gradient(const float depths[8], float displace) {
    float inverseCovariance = 1.0f / (8.0f * max(displace, 1e-30f));
    return vec2(1.41421356f * (depths[1] - depths[0]) + depths[5] + depths[7] - depths[4] - depths[6],
                1.41421356f * (depths[3] - depths[2]) + depths[6] + depths[7] - depths[4] - depths[5]) *
           inverseCovariance;
}

// The same in the reference's 4-wide SIMD form ("Optimizing with SIMD Vectorization"): axial = taps 0..3,
// diagonal = taps 4..7.
vec2 gsCircular8GradientVec4(vec4 axial, vec4 diagonal, float displace) {
    float inverseCovariance = 1.0f / (8.0f * max(displace, 1e-30f));
    vec2 axialTerm = vec2(axial.y - axial.x, axial.w - axial.z) * 1.41421356f;
    vec2 diagonalTerm = vec2(diagonal.y + diagonal.w - diagonal.x - diagonal.z,
                             diagonal.z + diagonal.w - diagonal.x - diagonal.y);
    return (axialTerm + diagonalTerm) * inverseCovariance;
}

// Second-order correction (the reference's "obvious improvement": higher-order derivatives). A least-squares
// quadric f(o) = a + g.o + 0.5 o^T H o over the taps; `fitRows` holds the precomputed 6 x N pseudo-inverse,
// row r at fitRows[r * GS_MAX_TAPS + i]. Returns g in xy and (Hxx, Hxy, Hyy) in `curvature`.
vec2 gsQuadraticFit(const float depths[GS_MAX_TAPS], int count, const float fitRows[6 * GS_MAX_TAPS], GS_OUT(vec3) curvature) {
    float coefficients[6];
    for (int r = 0; r < 6; ++r) {
        float sum = 0.0f;
        for (int i = 0; i < count; ++i) {
            sum += fitRows[r * GS_MAX_TAPS + i] * depths[i];
        }
        coefficients[r] = sum;
    }
    curvature = vec3(coefficients[3], coefficients[4], coefficients[5]);
    return vec2(coefficients[1], coefficients[2]);
}

// Depth change of the fitted quadric from the fragment to `offset`.
float gsQuadraticRise(vec2 offset, vec2 gradient, vec3 curvature) {
    return dot(offset, gradient) + 0.5f * curvature.x * offset.x * offset.x + curvature.y * offset.x * offset.y +
           0.5f * curvature.z * offset.y * offset.y;
}

const int GS_CORRECTION_NONE = 0;      // naive: every tap compared at the fragment's depth (Fig. 4.2.3)
const int GS_CORRECTION_POINT = 1;     // taps follow the fragment's own gradient
const int GS_CORRECTION_AVERAGE = 2;   // taps follow the least-squares gradient of the taps' depths
const int GS_CORRECTION_QUADRATIC = 3; // taps follow a least-squares quadric of the taps' depths
// Each tap at the nearer (to the light) of the point and average predictions. On a concave crease the average
// slope tilts towards the rising side: there it predicts nearer than the point gradient, on the fragment's own
// side farther; the nearer of the two is never worse than either (docs/SHADOWS.md).
const int GS_CORRECTION_NEARER = 4;

// PCF over GSM: the average of the fuzzy visibilities of the taps, each compared at the receiver depth the
// chosen correction predicts for it, or at the fragment's own where the prediction lies deeper. `pointGradient`,
// the fragment's own, drives GS_CORRECTION_POINT and is every correction's fuzzy width ("proportional to the
// local gradient", GSM reference, "Overview"): a fit over taps that straddle a caster's silhouette takes the
// jump's slope, and a band that wide lets a receiver far behind the caster through (terrain under a 1° sun: the
// average gradient leaked 33 of 20,830 shadowed pixels).
float gsPcfGsmVisibility(const float depths[GS_MAX_TAPS], const vec2 offsets[GS_MAX_TAPS], int count, float receiverDepth,
                         vec2 pointGradient, int correction, mat2 inverseCovariance,
                         const float fitRows[6 * GS_MAX_TAPS], float fuzzyScale, float minimumWidth) {
    vec2 gradient = pointGradient;
    vec3 curvature = vec3(0.0f);
    if (correction == GS_CORRECTION_AVERAGE || correction == GS_CORRECTION_NEARER) {
        gradient = gsLeastSquaresGradient(depths, offsets, count, inverseCovariance);
    } else if (correction == GS_CORRECTION_QUADRATIC) {
        gradient = gsQuadraticFit(depths, count, fitRows, curvature);
    }
    float magnitude = length(pointGradient);
    float sum = 0.0f;
    for (int i = 0; i < count; ++i) {
        // The receiver plane followed from the fragment to the tap (GSM multisampling reference, "Merging the
        // Algorithms", Figure 4.2.4b), or the fitted surface.
        float rise = 0.0f;
        if (correction == GS_CORRECTION_QUADRATIC) {
            rise = gsQuadraticRise(offsets[i], gradient, curvature);
        } else if (correction == GS_CORRECTION_NEARER) {
            rise = min(dot(offsets[i], gradient), dot(offsets[i], pointGradient));
        } else if (correction != GS_CORRECTION_NONE) {
            rise = dot(offsets[i], gradient);
        }
        float tapDepth = receiverDepth + gsNoDeeperThanFragment(rise);
        sum += gsFuzzyVisibility(depths[i], tapDepth, magnitude, fuzzyScale, minimumWidth);
    }
    return gsSaturate(sum / float(max(count, 1)));
}

// How far a step between neighbouring taps may stray from the fragment's own gradient and still join one
// surface, in multiples of that gradient's change over the step (gsPcfGsmConnectedVisibility). A crease between
// two faces changes the slope; a shadow's edge in the map is a jump that does not scale with the step.
const float GS_TAP_CONTINUITY = 4.0f;

// PCF over GSM with connected taps (ours; docs/SHADOWS.md, "Connected taps"). A shadow's edge is a silhouette
// seen from the light: a jump in the stored depth. A concave crease of the receiver is continuous there, only its
// slope changes, yet the far face rises in front of any plane through the fragment and fails every comparison
// (the darkening no gradient correction removes). So each tap is compared at the point gradient's prediction,
// never deeper than the fragment; one that fails is lit anyway when it continues, without a jump, a tap nearer
// the fragment within `linkDistance` texels that is attached to the fragment: it is the receiver's own surface.
// The innermost taps (none nearer within the link distance) are attached when they pass their comparison, the
// others only through such a chain, so a lit surface beyond a shadow's edge cannot reach into the shadow where
// its jump is small (a receiver nearly edge-on to the light). `order` lists the taps nearest the fragment
// first, so every tap's candidates are decided before it.
float gsPcfGsmConnectedVisibility(const float depths[GS_MAX_TAPS], const vec2 offsets[GS_MAX_TAPS],
                                  const int order[GS_MAX_TAPS], int count, float linkDistance,
                                  float receiverDepth, vec2 gradient, float fuzzyScale, float minimumWidth) {
    float slope = length(gradient);
    float visibility[GS_MAX_TAPS];
    float sum = 0.0f;
    for (int i = 0; i < count; ++i) {
        float tapDepth = receiverDepth + gsNoDeeperThanFragment(dot(offsets[i], gradient));
        visibility[i] = gsFuzzyVisibility(depths[i], tapDepth, slope, fuzzyScale, minimumWidth);
        sum += visibility[i];
    }
    if (sum >= float(count) || sum <= 0.0f) {
        return gsSaturate(sum / float(max(count, 1))); // all pass or all fail: no tap can attach another
    }
    bool attached[GS_MAX_TAPS];
    sum = 0.0f;
    for (int k = 0; k < count; ++k) {
        int i = order[k];
        float reach = length(offsets[i]) - 1e-4f * linkDistance;
        bool innermost = true;
        bool connected = false;
        for (int m = 0; m < k; ++m) {
            int j = order[m];
            vec2 step = offsets[i] - offsets[j];
            float stepLength = length(step);
            if (stepLength <= linkDistance && length(offsets[j]) < reach) {
                innermost = false;
                float deviation = abs(depths[i] - depths[j] - dot(step, gradient));
                connected = connected ||
                            (attached[j] && deviation <= GS_TAP_CONTINUITY * slope * stepLength + minimumWidth);
            }
        }
        attached[i] = connected || (innermost && visibility[i] >= 0.5f);
        sum += connected ? 1.0f : visibility[i];
    }
    return gsSaturate(sum / float(max(count, 1)));
}

// Receiver-plane bias for one comparison (bias reference, "Applications"): the surface depth extrapolated from
// the fragment along its plane (`gradient`, depth per texel) to a texel's centre or tap `toTap` texels away;
// with `clampToLit`, the bias may only move the receiver towards the light.
float gsReceiverPlaneTapDepth(float receiverDepth, vec2 toTap, vec2 gradient, bool clampToLit) {
    float bias = dot(toTap, gradient);
    return receiverDepth + (clampToLit ? gsNoDeeperThanFragment(bias) : bias);
}

// Bilinear blend of four comparisons laid out as textureGather returns them: x (-,+), y (+,+), z (+,-), w (-,-)
// relative to the sample point, `weights` the fractional position inside the 2x2 footprint.
float gsBilinear(vec4 visibilities, vec2 weights) {
    return mix(mix(visibilities.w, visibilities.z, weights.x), mix(visibilities.x, visibilities.y, weights.x),
               weights.y);
}

// ---- Percentage-closer soft shadows (Fernando, "Percentage-Closer Soft Shadows", SIGGRAPH 2005 sketch) ----

// The radius, in world units at the receiver, of the region of the map through which a light of `lightSize`
// reaches a receiver at `receiverDistance` past blockers at `blockerDistance`: the penumbra's half-width, by
// similar triangles. A sun (`perspective` false; distances along its rays, `lightSize` the tangent of its
// angular radius): (receiver - blocker) tan θ. A spot or point light (distances from it, `lightSize` its
// radius): r (receiver - blocker) / blocker. With the map's nearest distance for the blocker it is the blocker
// search's radius. Zero for a point light, or a blocker not nearer than the receiver; no more than `limit`.
float gsPcssRadius(float receiverDistance, float blockerDistance, float lightSize, bool perspective, float limit) {
    float span = receiverDistance - blockerDistance;
    if (!(span > 0.0f) || !(lightSize > 0.0f)) {
        return 0.0f;
    }
    float radius = perspective ? lightSize * span / max(blockerDistance, span * 1e-6f) : lightSize * span;
    return min(radius, limit);
}

// Tap `index` of `count` on a Vogel disk of unit radius (Vogel 1979: r = sqrt((i + 1/2) / n), turned by the
// golden angle from the tap before), the whole disk turned by `rotation` radians.
vec2 gsVogelTap(int index, int count, float rotation) {
    float radius = sqrt((float(index) + 0.5f) / float(max(count, 1)));
    float angle = float(index) * 2.39996323f + rotation;
    return vec2(cos(angle), sin(angle)) * radius;
}

// ---- Filtered shadow maps (advanced shadow mapping reference: VSM, MSM) ----

// The depth moments are taken of: a perspective map's [0,1] depth d crowds towards 1 as far/near grows (at
// far/near 1000 most of the scene lies above 0.99, where occluder and receiver differ by less than the
// minimum variance), so for perspective maps (`depthRange` = near, far > 0) the moments store the distance
// along the axis, normalised to [0,1]: z = n f / (f - d (f - n)), (z - n) / (f - n). Orthographic depth is
// already linear and passes through.
float gsLinearDepth(float depth, vec2 depthRange) {
    float near = depthRange.x;
    float far = depthRange.y;
    if (!(far > near) || !(near > 0.0f)) {
        return depth;
    }
    float distance = near * far / max(far - depth * (far - near), near * 1e-6f);
    return gsSaturate((distance - near) / (far - near));
}

// Variance shadow maps (Donnelly & Lauritzen 2006): Chebyshev's one-tailed bound on the fraction of the filter
// region at or behind the receiver. The early return where the mean lies beyond the receiver is the reference's
// (without it the bound darkens fully lit surfaces). `bleedingReduction` cuts the bound's tail (linstep), the
// usual remedy for light bleeding.
float gsChebyshevVisibility(vec2 moments, float depth, float minimumVariance, float bleedingReduction) {
    if (depth <= moments.x) {
        return 1.0f;
    }
    float variance = max(moments.y - moments.x * moments.x, max(minimumVariance, 1e-30f));
    float distance = depth - moments.x;
    float bound = variance / (variance + distance * distance);
    return gsSaturate((bound - bleedingReduction) / max(1.0f - bleedingReduction, 1e-6f));
}

// Exponential variance shadow maps (Lauritzen & McCool, "Layered variance shadow maps", GI 2008, section on
// exponential warping; as Filament and Unity HDRP ship them): depth d warped to exp(c+ d) and -exp(-c- d). Both
// warps increase with d, so Chebyshev's bound holds for each, and a receiver's bound is the smaller of the two;
// the steep warps shrink the variance an occluder's neighbourhood adds, which is what VSM's light bleeding is.
// Exponents up to 42 keep exp(2c) finite in float32.
vec2 gsEvsmWarp(float depth, vec2 exponents) {
    return vec2(exp(exponents.x * depth), -exp(-exponents.y * depth));
}

// What the shadow pass stores: both warps and their squares.
vec4 gsEvsmMoments(float depth, vec2 exponents) {
    vec2 warped = gsEvsmWarp(depth, exponents);
    return vec4(warped.x, warped.x * warped.x, warped.y, warped.y * warped.y);
}

// `minimumVariance` is in depth units squared; in a warp's space it scales by the warp's slope squared
// (d/dd of exp(c d) is c exp(c d)), which also keeps it above float32's cancellation in m2 - m1^2.
float gsEvsmVisibility(vec4 moments, float depth, vec2 exponents, float minimumVariance, float bleedingReduction) {
    vec2 warped = gsEvsmWarp(depth, exponents);
    vec2 slope = exponents * warped;
    float positive = gsChebyshevVisibility(vec2(moments.x, moments.y), warped.x, minimumVariance * slope.x * slope.x,
                                           bleedingReduction);
    float negative = gsChebyshevVisibility(vec2(moments.z, moments.w), warped.y, minimumVariance * slope.y * slope.y,
                                           bleedingReduction);
    return min(positive, negative);
}

// Moment shadow mapping, four moments, Hamburger bound (Peters & Klein 2015, Algorithm 2, as in the reference):
// bias the moments towards (0, 0.63, 0, 0.63), solve the 3x3 Hankel system by Cholesky, find the two other
// support points z2 <= z3 of the bound's distribution, then the three cases. Every pivot and denominator is
// guarded, so singular moments (a constant-depth texel) and negative discriminants stay finite. Returns the
// biased moments' first two (b1, b2) in `biased` for gsMsmBlocker.
vec2 gsMsmSupport(vec4 moments, float depth, float momentBias, GS_OUT(vec2) biased) {
    vec4 b = mix(moments, vec4(0.0f, 0.63f, 0.0f, 0.63f), momentBias);
    biased = vec2(b.x, b.y);
    // Cholesky factorisation B = L D L^T of B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]].
    float l21 = b.x;
    float d22 = max(b.y - b.x * b.x, 1e-12f);
    float l31 = b.y;
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = max(b.w - b.y * b.y - l32 * l32 * d22, 1e-12f);
    // Solve B c = (1, z, z^2): forward substitution, diagonal, back substitution.
    float y2 = depth - l21;
    float y3 = depth * depth - l31 - l32 * y2;
    float c3 = y3 / d33;
    float c2 = y2 / d22 - l32 * c3;
    float c1 = 1.0f - l21 * c2 - l31 * c3;
    // Roots of c3 z^2 + c2 z + c1 = 0.
    float safeC3 = abs(c3) > 1e-20f ? c3 : (c3 < 0.0f ? -1e-20f : 1e-20f);
    float p = c2 / safeC3;
    float q = c1 / safeC3;
    float root = sqrt(max(0.25f * p * p - q, 0.0f));
    return vec2(-0.5f * p - root, -0.5f * p + root);
}

float gsMsmVisibility(vec4 moments, float depth, float momentBias) {
    vec2 b;
    vec2 support = gsMsmSupport(moments, depth, momentBias, b);
    float z2 = support.x;
    float z3 = support.y;
    float shadow;
    if (depth <= z2) {
        shadow = 0.0f;
    } else if (depth <= z3) {
        shadow = (depth * z3 - b.x * (depth + z3) + b.y) / max((z3 - z2) * (depth - z2), 1e-20f);
    } else {
        shadow = 1.0f - (z2 * z3 - b.x * (z2 + z3) + b.y) / max((depth - z2) * (depth - z3), 1e-20f);
    }
    float visibility = 1.0f - shadow;
    return visibility == visibility ? gsSaturate(visibility) : 1.0f; // NaN only from NaN input: treat as lit
}

// The blockers of a filter region from its moments (moment soft shadow mapping's blocker search, Peters et al.,
// I3D 2016, section 4): the bound's distribution has its atoms at the receiver `depth`, z2 and z3, with the
// weights that reproduce the moments (Vandermonde: w2 = (d z3 - b1 (d + z3) + b2) / ((z2 - d)(z2 - z3)), w3
// with z2 and z3 swapped); the atoms in front of the receiver are the blockers. Returns their mean depth,
// weighted, and their fraction of the region in `fraction` (Hamburger's shadow intensity): 0 where no atom is
// in front, when the mean is the receiver's own depth.
float gsMsmBlocker(vec4 moments, float depth, float momentBias, GS_OUT(float) fraction) {
    vec2 b;
    vec2 support = gsMsmSupport(moments, depth, momentBias, b);
    float z2 = support.x;
    float z3 = support.y;
    fraction = 0.0f;
    if (!(depth > z2)) {
        return depth; // nothing in front of the receiver (or NaN input)
    }
    float w2 = gsSaturate((depth * z3 - b.x * (depth + z3) + b.y) / max((z3 - z2) * (depth - z2), 1e-20f));
    if (depth <= z3) {
        fraction = w2;
        return z2;
    }
    float w3 = gsSaturate((b.x * (depth + z2) - depth * z2 - b.y) / max((z3 - z2) * (depth - z3), 1e-20f));
    fraction = gsSaturate(w2 + w3);
    return w2 + w3 > 1e-12f ? (w2 * z2 + w3 * z3) / (w2 + w3) : z2;
}

// The optimised moment basis of Peters & Klein 2015 ("Optimized Moment Quantization"): an affine transform that
// makes (z, z^2, z^3, z^4) fit 16-bit unorm storage with little error. Columns hold the published matrix's rows.
const mat4 GS_MSM_QUANTIZE = mat4(-2.07224649f, 13.7948857237f, 0.105877704f, 9.7924062118f,
                                  32.23703778f, -59.4683975703f, -1.9077466311f, -33.7652110555f,
                                  -68.571074599f, 82.0359750338f, 9.3496555107f, 47.9456096605f,
                                  39.3703274134f, -35.364903257f, -6.6543490743f, -23.9728048165f);
const vec4 GS_MSM_QUANTIZE_OFFSET = vec4(0.035955884801f, 0.0f, 0.0f, 0.0f);

vec4 gsMsmMoments(float depth) {
    float square = depth * depth;
    return vec4(depth, square, square * depth, square * square);
}

vec4 gsMsmQuantize(vec4 moments) { return GS_MSM_QUANTIZE * moments + GS_MSM_QUANTIZE_OFFSET; }

// `inverseQuantize` is inverse(GS_MSM_QUANTIZE), computed once on the CPU.
vec4 gsMsmDequantize(vec4 quantized, mat4 inverseQuantize) {
    return inverseQuantize * (quantized - GS_MSM_QUANTIZE_OFFSET);
}

// Pixel shader branching (soft shadows reference): the test taps' hard comparisons decide whether the pixel can
// be in a penumbra. Returns true when they all agree (fully lit or fully shadowed: no more taps needed).
bool gsTestTapsAgree(float litCount, float testCount) { return litCount == 0.0f || litCount == testCount; }

// ---- Lights with several maps: cascades of a directional light, the six faces of a point light ----

// Cube face of the direction `d` from a point light: the axis of largest magnitude, +X 0, -X 1, +Y 2, -Y 3,
// +Z 4, -Z 5 (the order of GL's cube map faces). Ties go to the earlier axis, so every direction has exactly one
// face; on an edge both faces' maps hold the point (their frustums are widened by a margin, ShadowModule), which
// keeps the selection's switch invisible.
int gsCubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) {
        return d.x >= 0.0f ? 0 : 1;
    }
    if (a.y >= a.z) {
        return d.y >= 0.0f ? 2 : 3;
    }
    return d.z >= 0.0f ? 4 : 5;
}

// Cascade of a receiver at view depth `depth`: the first whose far split (`splitFar`, ascending, `count` of
// them) lies beyond it; the last for anything farther.
int gsCascadeIndex(float depth, vec4 splitFar, int count) {
    for (int i = 0; i < count - 1; ++i) {
        if (depth < splitFar[i]) {
            return i;
        }
    }
    return max(count - 1, 0);
}

// Weight of the next cascade in the blend band at the far end of a cascade spanning [start, end]: 0 before the
// band (the last `blend` fraction of the span), rising linearly to 1 at `end`.
float gsCascadeBlendWeight(float depth, float start, float end, float blend) {
    float band = blend * (end - start);
    if (!(band > 0.0f)) {
        return 0.0f;
    }
    return gsSaturate((depth - (end - band)) / band);
}

// Lloyd, Tuft, Yoon, Manocha, "Warping and Partitioning for Low Error Shadow Maps" (EGSR 2006), section 3:
// the aliasing error m is the largest extent, in screen pixels, of one shadow texel seen in the image. With
// the texel coordinates' screen derivatives as the columns of J = d(texel)/d(pixel), a unit texel covers
// J^-1's image of a unit square, whose largest extent is 1/sigma_min(J) = sigma_max(J) / |det J|. m <= 1 is
// one texel per pixel or finer. A singular J (a receiver edge-on to the light or to the camera) gives
// GS_FOOTPRINT_UNBOUNDED.
const float GS_FOOTPRINT_UNBOUNDED = 1e30f;
float gsTexelFootprintPixels(vec2 texelPerPixelX, vec2 texelPerPixelY) {
    // Scaled first, so that the squares neither overflow for huge derivatives nor underflow for tiny ones.
    float scale = max(max(abs(texelPerPixelX.x), abs(texelPerPixelX.y)),
                      max(abs(texelPerPixelY.x), abs(texelPerPixelY.y)));
    if (!(scale > 0.0f && scale <= 3.0e38f)) { // zero, infinite or NaN
        return GS_FOOTPRINT_UNBOUNDED;
    }
    vec2 x = texelPerPixelX / scale;
    vec2 y = texelPerPixelY / scale;
    float a = dot(x, x);
    float b = dot(x, y);
    float c = dot(y, y);
    float halfDifference = 0.5f * (a - c);
    float largest = sqrt(max(0.5f * (a + c) + sqrt(halfDifference * halfDifference + b * b), 0.0f));
    float determinant = abs(x.x * y.y - x.y * y.x);
    if (!(determinant > 1e-12f * largest * largest)) {
        return GS_FOOTPRINT_UNBOUNDED;
    }
    return min(largest / (determinant * scale), GS_FOOTPRINT_UNBOUNDED);
}

// Virtual maps: the absolute clipmap level a receiver asks for, level k having texels 2^k world units wide. A
// texel's footprint grows with its size, m = 2^k * unitFootprint (gsTexelFootprintPixels of a texel one world
// unit wide), so the coarsest level with m <= 1 is floor(-log2(unitFootprint)): the receiver's slope to the
// light and to the camera both count, which a level from distance alone (Unreal's) leaves out. Near grazing
// light m grows without bound; no texel meets it there, so the slope may ask for at most
// GS_VIRTUAL_SLOPE_OCTAVES levels finer than the pixel's own world size `pixelSize` does. A receiver whose
// footprint is unknown (NaN, zero, unbounded) asks by its pixel size alone. Clamped to [base, base + count - 1].
const int GS_VIRTUAL_SLOPE_OCTAVES = 3;
int gsVirtualLevel(float unitFootprint, float pixelSize, int base, int count) {
    float byPixel = pixelSize > 0.0f && pixelSize < 3.0e38f ? floor(log2(pixelSize)) : float(base);
    float level = byPixel;
    if (unitFootprint > 0.0f && unitFootprint < GS_FOOTPRINT_UNBOUNDED) {
        level = max(floor(-log2(unitFootprint)), byPixel - float(GS_VIRTUAL_SLOPE_OCTAVES));
    }
    return clamp(int(level), base, base + count - 1);
}

// Virtual maps of spot and point lights: the mip level, of `levels`, a receiver asks for in a perspective map,
// level m having texels 2^m level-0 texels wide. `texelPerPixelX`/`Y` are the receiver's level-0 texel
// coordinates per pixel, `pixelTexels` its pixel's world size in level-0 texels there; the rule is
// gsVirtualLevel's with level-0 texels as the unit of length, aiming at `texelPixels` (ShadowSettings::
// virtualTexelPixels) pixels a texel.
int gsVirtualFaceLevel(vec2 texelPerPixelX, vec2 texelPerPixelY, float pixelTexels, float texelPixels,
                       int levels) {
    float footprint = gsTexelFootprintPixels(texelPerPixelX, texelPerPixelY);
    footprint = footprint < GS_FOOTPRINT_UNBOUNDED ? footprint / texelPixels : footprint;
    return gsVirtualLevel(footprint, pixelTexels * texelPixels, 0, levels);
}

// The pages a lookup at window texel `texel` reads when its offsets and kernel reach `reach` texels: from
// `low` to `high` inclusive, clamped to the window of `pagesPerSide` pages of `pageSize` texels.
void gsVirtualPageSpan(vec2 texel, float reach, float pageSize, int pagesPerSide, GS_OUT(ivec2) low,
                       GS_OUT(ivec2) high) {
    low = clamp(ivec2(floor((texel - reach) / pageSize)), ivec2(0), ivec2(pagesPerSide - 1));
    high = clamp(ivec2(floor((texel + reach) / pageSize)), ivec2(0), ivec2(pagesPerSide - 1));
}
