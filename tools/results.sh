#!/usr/bin/env bash
# Regenerates docs/RESULTS.md (and docs/results/*.png) from a fresh shadowbench sweep on this machine.
# Usage: bash tools/results.sh [--only real|defaults|filtered|lights|virtual|soft|cost|sizing|still] [work folder,
# default out/results]
# --only real runs steps 4 to 6 alone, --only defaults steps 4 to 7 (the recommendation weighs the real models' frame
# times), --only filtered step 3, --only lights step 8, --only virtual step 11 (with the osgShadow peer's VDSM rows it
# reads), --only soft step 12, --only cost step 10, --only sizing step 13, --only still step 14 (with its VDSM rows),
# and replaces only those steps' sections of docs/RESULTS.md ("Real models"; those and "Defaults" and "PCF over GSM
# against single-tap GSM"; "Filtered families: ..."; "Every light: cascades and point lights"; "Virtual maps", "Soft
# shadows", "Cost model", "Maps sized to the view", "A still view keeps its maps"), which then say so.
set -euo pipefail
cd "$(dirname "$0")/.."
only=()
if [ "${1:-}" = --only ]; then
    case "${2:-}" in
        real | defaults | filtered | lights | virtual | soft | cost | sizing | still) only=(--only "$2") ;;
        *) echo "results.sh: --only takes 'real', 'defaults', 'filtered', 'lights', 'virtual', 'soft', 'cost', 'sizing'" \
               "or 'still'" >&2
           exit 2 ;;
    esac
    shift 2
fi
work=${1:-out/results}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-shadowbench gs-render gs-corpus gs-osgshadow
bench=./build/bin/gs-shadowbench
rm -rf "$work"

corpus=(suzanne human-subdivided fzk-haus at-at jeep duck wuson epileptic dwarf cylinder-engine terrain)
peer_run() { # peer_run SCENE_FILE PREFIX OPTION...: one peer run, into PREFIX.json, .png and .visibility.pfm
    local scene=$1 prefix=$2
    shift 2
    xvfb-run -a -s "-screen 0 1280x1024x24" ./build/bin/gs-osgshadow --scene "$scene" "$@" \
        --size 640x480 --map-size 2048 --frames 9 --warmup 3 --out "$prefix"
}
peer_as() { # peer_as SCENE_FILE NAME OPTION...: one peer run, into $work/osg/<scene stem>/NAME
    local scene=$1 name=$2
    shift 2
    peer_run "$scene" "$work/osg/$(basename "${scene%.*}")/$name" "$@"
}
peer_rounds() { # peer_rounds SCENE STEP COMMAND...: 3 rounds of COMMAND, each given its round as a last argument,
    # the peer's VDSM timed before the first (unless a run just before left it there) and after each, into
    # $work/osg-STEP/SCENE/<n> (results.py load_rounds):
    # the machine's speed drifts by up to 2x within a minute, so each round is compared with its neighbours.
    local scene=$1 step=$2 round
    shift 2
    [ -e "$work/osg-$step/$scene/0.json" ] || peer_run "corpus/$scene.glb" "$work/osg-$step/$scene/0" --technique vdsm
    for round in 1 2 3; do
        "$@" "$round"
        peer_run "corpus/$scene.glb" "$work/osg-$step/$scene/$round" --technique vdsm
    done
}
peer() { # peer SCENE_FILE TECHNIQUE...: each technique's run at OSG's defaults, named after it
    local scene=$1 technique
    shift
    for technique in "$@"; do
        peer_as "$scene" "$technique" --technique "$technique"
    done
}
defaults_views() { # defaults_views OUT OPTION...: the Defaults views, accuracy only, 320x240, into OUT-own, -swept, -large
    # Every content scene and real model under its own light, the terrain seen from 10 m above its ground, then the
    # same scenes under a sweep of azimuths x elevations down to 1° above the horizon, then the generated apron (one
    # mesh per object, and all in one mesh) under suns at 40, 15, 8 and 3 degrees.
    local out=$1 views=(knob torus bowl thin-shell crease-cube grazing-plane spheres "${corpus[@]}")
    shift
    "$bench" --defaults --accuracy-only --size 320x240 $(printf -- '--scene %s ' "${views[@]}") --scene terrain-low \
        "$@" --out "$out-own"
    "$bench" --defaults --accuracy-only --size 320x240 $(printf -- '--scene %s ' "${views[@]}") \
        --light-sweep 30,210:40,5,1 "$@" --out "$out-swept"
    "$bench" --defaults --accuracy-only --size 320x240 --scene apron --scene apron-merged --light-sweep 75:40,15,8,3 \
        "$@" --out "$out-large"
}

real_models_steps() { # steps 4 to 6, the "Real models" section, which the full run and --only real run
    # 4. Real models (tools/corpus.sh) at 640x480 with 2048² maps: every technique, and every osgShadow technique of
    #    the OpenSceneGraph peer on the same scene, camera and light, measured against the same ray-traced truth; our
    #    techniques timed in turn in each of 3 rounds, alternated with the peer's VDSM (peer_rounds).
    bash tools/corpus.sh
    real_timed() { # real_timed SCENE ROUND
        "$bench" --scene "$1" --taps 4 --resolutions 2048 --frames 2 --peer "$work/osg" --out "$work/real/$1/$2"
    }
    for model in "${corpus[@]}"; do
        peer "corpus/$model.glb" sm lispsm ssm vdsm
        # The VDSM run the accuracy rows read is also the first of the runs bracketing the rounds.
        mkdir -p "$work/osg-real/$model"
        cp "$work/osg/$model/vdsm.json" "$work/osg-real/$model/0.json"
        peer_rounds "$model" real real_timed "$model"
    done

    # 5. Frame-time scaling from 10k to 1M triangles (generated hills): ours without shadows and with gsm, the peer
    #    without shadows and with ViewDependentShadowMap.
    sweep=()
    for triangles in 10000 100000 1000000; do
        peer "corpus/sweep/hills-$triangles.glb" vdsm
        sweep+=(--scene "corpus/sweep/hills-$triangles.glb")
    done
    "$bench" "${sweep[@]}" --techniques gsm --resolutions 2048 --frames 5 --peer "$work/osg" --out "$work/scaling"

    # 6. What the renderer's options do, side by side in one run (gs-render, whole frames): the depth pre-pass, glibc's
    #    default allocator thresholds instead of the tuned ones, meshes drawn whole instead of in chunks, and every
    #    face drawn, the hidden faces of closed meshes too, in the lighting pass and the shadow pass; the
    #    defaults run twice, so the table shows how far two identical runs differ. Every frame draws its shadow maps
    #    (--redraw-maps), as a moving view's do, so the shadow pass's draws are among what the options change.
    for model in knob fzk-haus cylinder-engine suzanne terrain; do
        for technique in none gsm pcf-gsm-average; do
            for variant in plain prepass default-allocator unchunked every-face plain-again; do
                case $variant in
                    plain | plain-again) options=() ;;
                    prepass) options=(--depth-prepass) ;;
                    default-allocator) options=(--allocator default) ;;
                    unchunked) options=(--chunk-triangles 16777216) ;;
                    every-face) options=(--draw-hidden-faces --caster-faces both) ;;
                esac
                ./build/bin/gs-render --scene "$model" --technique "$technique" --size 640x480 --frames 15 --redraw-maps \
                    "${options[@]}" --out "$work/engine/$model/$technique-$variant" >/dev/null
            done
        done
    done
    # The sRGB encode's cost in the unshadowed frame of small models, where the per-pixel work is most of it: the
    # colour stored as computed (--linear-output, as the peer's fixed-function pass stores it) alternated with the
    # defaults over 5 rounds, since one run of each differs by less than two identical runs do.
    for model in knob duck at-at dwarf; do
        for round in 1 2 3 4 5; do
            for variant in plain linear-output; do
                options=()
                [ "$variant" = plain ] || options=(--linear-output)
                ./build/bin/gs-render --scene "$model" --technique none --size 640x480 --frames 15 "${options[@]}" \
                    --out "$work/encode/$model/$variant-$round" >/dev/null
            done
        done
    done
}

if [ ${#only[@]} -eq 0 ]; then # steps 1-10: the full run
# 1. Trade-off sweep on the default scene: every technique, tap counts and map sizes.
"$bench" --scene knob --taps 2,4,6 --resolutions 512,1024,2048 --frames 7 --out "$work/knob-sweep"

# 2. Every stress scene at one map size (spheres: a spot light), plus the reproductions of the references' claims.
"$bench" --scene torus --scene bowl --scene thin-shell --scene crease-cube --scene grazing-plane --scene spheres \
    --taps 4 --resolutions 1024 --frames 5 --out "$work/scenes"
# The corrections of PCF over GSM as the reference has them: without the module's normal offset, and with the
# map's own gradient (central differences).
reference="pcfTaps=5,pcfRadius=2,resolution=1024,footprintNormalOffset=false,gradientSource=central"
"$bench" --scene knob --techniques pcf,pcf-gsm-naive --taps 5 --radius 2 --resolutions 1024 --frames 15 \
    --config "pcf-gsm-point-5x5-1024-d24:technique=pcf-gsm-point,$reference" \
    --config "pcf-gsm-average-5x5-1024-d24:technique=pcf-gsm-average,$reference" \
    --config "pcf-gsm-quadratic-5x5-1024-d24:technique=pcf-gsm-quadratic,$reference" \
    --config "rpb-d16-round:technique=receiver-plane,depthFormat=d16,footprintNormalOffset=false" \
    --config "rpb-d16-floor:technique=receiver-plane,depthFormat=d16,floorReceiverDepth=true,footprintNormalOffset=false" \
    --config "rpb-d24-round:technique=receiver-plane,depthFormat=d24,footprintNormalOffset=false" \
    --config "rpb-d24-floor:technique=receiver-plane,depthFormat=d24,floorReceiverDepth=true,footprintNormalOffset=false" \
    --config "average-circular8:technique=pcf-gsm-average,averageGradientForm=circular8,pcfRadius=1,footprintNormalOffset=false" \
    --config "average-circular8-vec4:technique=pcf-gsm-average,averageGradientForm=circular8-vec4,pcfRadius=1,footprintNormalOffset=false" \
    --config "naive-circular8:technique=pcf-gsm-naive,pcfLayout=circular8,pcfRadius=1" \
    --out "$work/reproduction"

real_models_steps

# 7. Defaults: every technique at its defaults over the Defaults views (defaults_views), accuracy only (the Defaults
#    table).
defaults_views "$work/defaults"


# 9. Fitted to what the screen sees: the maps fitted to the visible depth samples (the default) against mesh bounds,
#    timed at 640x480 with 2048² maps, on the large views and two models; then shimmer along a camera path (the
#    maps fitted to each frame's view), snapped, unsnapped and fitted to bounds.
bounds=()
for technique in evsm slope-scaled gsm pcf; do
    bounds+=(--config "$technique-bounds:technique=$technique,directionalFit=bounds")
done
"$bench" --scene apron-merged --scene apron --scene terrain-low --scene terrain --scene knob --scene cylinder-engine \
    --defaults --techniques evsm,slope-scaled,gsm,pcf "${bounds[@]}" --frames 3 --out "$work/fit"
"$bench" --scene knob --scene outdoor --scene terrain --scene apron-merged --techniques default --resolutions 2048 \
    --accuracy-only --size 320x240 --shimmer-path 16 --config "unsnapped:texelSnapping=false,resolution=2048" \
    --config "bounds:directionalFit=bounds,resolution=2048" --out "$work/path-shimmer"

elif [ "${only[1]}" = real ]; then
    real_models_steps
elif [ "${only[1]}" = defaults ]; then
    real_models_steps
    defaults_views "$work/defaults"
elif [ "${only[1]}" = virtual ]; then
    # The peer rows step 11 reads: VDSM on its scenes the peer has (step 4 runs these among the others).
    bash tools/corpus.sh
    for model in suzanne fzk-haus cylinder-engine terrain; do
        peer "corpus/$model.glb" vdsm
    done
fi

if [ "${only[1]:-lights}" = lights ]; then
# 8. Every light. The 4 km outdoor scene under its sun: the default technique with 1-4 cascades and several
#    split weights, timed, against the truth, and its shimmer while the view the maps are fitted to moves by
#    sub-texel steps, snapped and not; osgShadow's cascaded techniques on the same view in the same table. Then
#    every technique at its defaults on the outdoor scene (automatic cascades) and in the point-light room.
outdoor=content/scenes/outdoor.gltf
peer_as "$outdoor" vdsm --technique vdsm
peer_as "$outdoor" vdsm-csm2 --technique vdsm --cascades 2
for splits in 1 2 3 4; do
    peer_as "$outdoor" "pssm$splits" --technique pssm --splits "$splits"
done
cascades=(--config "c1:cascadeCount=1" --config "c1-unsnapped:cascadeCount=1,texelSnapping=false")
for count in 2 3 4; do
    for weight in 0.5 0.75 0.9 0.97; do
        cascades+=(--config "c$count-w$weight:cascadeCount=$count,cascadeSplitWeight=$weight")
    done
done
cascades+=(--config "c4-w0.9-unsnapped:cascadeCount=4,cascadeSplitWeight=0.9,texelSnapping=false")
"$bench" --scene outdoor --techniques default --resolutions 2048 --frames 5 --shimmer 8 "${cascades[@]}" \
    --peer "$work/osg" --out "$work/outdoor-cascades"
"$bench" --defaults --scene outdoor --scene room --frames 5 --out "$work/every-light"
fi

if [ "${only[1]:-filtered}" = filtered ]; then
[ ${#only[@]} -eq 0 ] || bash tools/corpus.sh
# 3. Filtered families: VSM, EVSM and MSM light leaking, and early-out speed versus the same jittered kernel.
"$bench" --scene knob --scene thin-shell --scene spheres --techniques vsm,evsm,msm --resolutions 1024 --frames 7 \
    --config "vsm-32bit:technique=vsm,moments16=false,resolution=1024" \
    --config "msm-32bit:technique=msm,moments16=false,resolution=1024" \
    --config "vsm-no-reduction:technique=vsm,lightBleedingReduction=0,resolution=1024" \
    --config "jittered32-full:technique=pcf-jittered,jitterTaps=32,earlyOutTestTaps=0,resolution=1024" \
    --config "jittered32-early8:technique=pcf-jittered,jitterTaps=32,earlyOutTestTaps=8,resolution=1024" \
    --config "jittered64-full:technique=pcf-jittered,jitterTaps=64,earlyOutTestTaps=0,resolution=1024" \
    --config "jittered64-early16:technique=pcf-jittered,jitterTaps=64,earlyOutTestTaps=16,resolution=1024" \
    --out "$work/filtered"
#    The moments' precision over the Defaults views: vsm and msm at their defaults (16-bit moments) and in 32-bit
#    floats, accuracy only.
moments32=(--config "vsm-32bit:technique=vsm,moments16=false" --config "msm-32bit:technique=msm,moments16=false")
defaults_views "$work/moments16" --techniques vsm,msm "${moments32[@]}"
#    and on the 4 km outdoor scene's cascades and the room's cube faces, 640x480.
"$bench" --defaults --accuracy-only --scene outdoor --scene room --techniques vsm,msm "${moments32[@]}" \
    --out "$work/moments16-lights"
fi

if [ "${only[1]:-cost}" = cost ]; then
[ ${#only[@]} -eq 0 ] || bash tools/corpus.sh
# 10. The cost model: every technique at its defaults, timed, on a real model, the generated apron (one mesh) and
#     the knob, the default technique at the other depth formats too, with the reference pass's cost of one more
#     read per fragment on each and of one read of maps of other sizes and formats (--cost-model); then each
#     variant's instructions as Mesa compiles them (MESA_GLSL=dump).
"$bench" --scene cylinder-engine --scene apron-merged --scene knob --defaults --cost-model --frames 5 \
    --config "slope-scaled-d16:technique=slope-scaled,depthFormat=d16" \
    --config "slope-scaled-d32f:technique=slope-scaled,depthFormat=d32f" --out "$work/cost-model"
/usr/bin/python3 tools/shadowbench/nir_counts.py ./build/bin/gs-render "$work/cost-model/nir-counts.json"
fi

if [ "${only[1]:-virtual}" = virtual ]; then
# 11. Virtual maps: the default technique with whole fitted maps and with virtual maps, timed, with its pages cold
#     and while the camera walks, on the large views, the knob and real models, osgShadow's VDSM beside it where
#     the peer has the scene (3 rounds there, alternated with the peer's, peer_rounds); then the apron under suns
#     down to 3°, accuracy only.
virtual_timed() { # virtual_timed SCENE ROUND
    "$bench" --scene "$1" --techniques default --resolutions 2048 --config "virtual:mapAllocation=virtual" \
        --frames 5 --walk 30 --peer "$work/osg" --out "$work/virtual/$1/$2"
}
for scene in apron-merged apron terrain-low knob; do
    virtual_timed "$scene" 1
done
for scene in terrain cylinder-engine fzk-haus suzanne; do
    peer_rounds "$scene" virtual virtual_timed "$scene"
done
"$bench" --scene apron --scene apron-merged --light-sweep 75:40,15,8,3 --techniques default --resolutions 2048 \
    --config "virtual:mapAllocation=virtual" --accuracy-only --out "$work/virtual-suns"
#     The texel size the pages are drawn for (virtualTexelPixels) against the texels they take, accuracy only.
"$bench" --scene apron-merged --scene terrain-low --scene terrain --scene knob --scene cylinder-engine \
    --techniques default --resolutions 2048 --config "m1:mapAllocation=virtual" --config "m2:mapAllocation=virtual,virtualTexelPixels=2" \
    --config "m4:mapAllocation=virtual,virtualTexelPixels=4" --accuracy-only --walk 30 --out "$work/virtual-texels"
#     Spot and point lights: the room's two point lights and the spheres' spot, the default technique and msm (the
#     room's 960 MiB of fitted moment faces), fitted and virtual.
"$bench" --scene room --scene spheres --techniques default,msm --resolutions 2048 --config "virtual:mapAllocation=virtual" \
    --config "virtual-msm:technique=msm,mapAllocation=virtual" --frames 5 --walk 30 --out "$work/virtual-lights"
fi

if [ "${only[1]:-soft}" = soft ]; then
# 12. Soft shadows: pcss, its naive reproduction, msm-soft, the default and the filtered techniques against the
#     ray-traced truth of each light's own size (8² rays a pixel, and its distance from 16²), on the soft-shadow
#     scenes, the room and the outdoor scene, at 2048² and (where the soft techniques' reach holds the widest
#     penumbrae) 256².
"$bench" --scene soft-contact --scene soft-overlap --scene soft-fence --scene room --scene outdoor \
    --techniques default,pcf,gsm,evsm,msm,pcss,pcss-screen-plane,msm-soft --resolutions 2048 --soft 8 \
    --accuracy-only --out "$work/soft"
"$bench" --scene soft-contact --scene soft-overlap --techniques pcss,msm-soft --resolutions 256 --soft 8 \
    --accuracy-only --out "$work/soft-coarse"
#     Cascade seams: the wall and the fence with 4 cascades, where the seams cross their penumbrae.
"$bench" --scene soft-contact --scene soft-fence --techniques pcss --resolutions 2048 --soft 8 --accuracy-only \
    --config "pcss-4-cascades:technique=pcss,cascadeCount=4" \
    --config "msm-soft-4-cascades:technique=msm-soft,cascadeCount=4" --out "$work/soft-seams"
fi

if [ "${only[1]:-sizing}" = sizing ]; then
# 13. Maps sized to the view: the default technique with its directional map sized to what the view resolves
#     (fittedTexelPixels: the default, half a pixel and a pixel), at the full 2048² (fittedTexelPixels=0), as
#     virtual maps and in 16-bit depth, timed, on content scenes and real models, 640x480, the configurations
#     alternated over 5 rounds.
[ ${#only[@]} -eq 0 ] || bash tools/corpus.sh
sizing_alternatives=(--config "virtual:mapAllocation=virtual" --config "d16:depthFormat=d16")
"$bench" --scene knob --scene spheres --scene suzanne --scene fzk-haus --scene duck --scene cylinder-engine \
    --scene terrain --scene apron-merged --techniques default --resolutions 2048 --size 640x480 --frames 3 --rounds 5 \
    --config "full-2048:fittedTexelPixels=0" --config "texel-0.5:fittedTexelPixels=0.5" \
    --config "texel-1:fittedTexelPixels=1" "${sizing_alternatives[@]}" --out "$work/sizing"
#     The same configurations over the Defaults views, accuracy only: which views each keeps within the floor.
defaults_views "$work/sizing-floor" --techniques default --config "full-2048:fittedTexelPixels=0" \
    --config "texel-0.5:fittedTexelPixels=0.5" --config "texel-1:fittedTexelPixels=1" "${sizing_alternatives[@]}"
fi

if [ "${only[1]:-still}" = still ]; then
# 14. A still view keeps its maps: the default technique on every real model and the generated apron (one mesh),
#     timed with every frame drawing its maps, as a moving view's do, and on the still view, which keeps them;
#     osgShadow's ViewDependentShadowMap beside it (step 4 ran the peer on the models for its edges; the apron's run
#     is here). Each scene runs 3 rounds of ours alternated with the peer's (peer_rounds).
if [ ${#only[@]} -gt 0 ]; then
    bash tools/corpus.sh
    for model in "${corpus[@]}"; do
        peer "corpus/$model.glb" vdsm
    done
fi
peer corpus/apron-merged.glb vdsm
still_timed() { # still_timed SCENE ROUND
    "$bench" --scene "$1" --techniques default --resolutions 2048 --size 640x480 --frames 7 --walk 30 \
        --peer "$work/osg" --out "$work/still/$1/$2"
}
for scene in "${corpus[@]}" apron-merged; do
    peer_rounds "$scene" still still_timed "$scene"
done
fi

# Debian's interpreter: python3-matplotlib installs there (a python3 earlier on PATH may lack it).
/usr/bin/python3 tools/shadowbench/results.py "$work" docs/RESULTS.md docs/results "${only[@]}"
echo "wrote docs/RESULTS.md"
