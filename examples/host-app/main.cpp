// host-app: the smallest useful host of an installed Gradient Shadows. Loads a glTF scene, attaches the
// shadow module (linked into this program, or with --plugin loaded by name from libgs_module_shadows.so),
// renders headless through EGL to a PNG and prints the frame time.
//
// usage: host-app SCENE.gltf OUT.png [--plugin]
#include <content/GltfLoader.h>
#include <engine/Engine.h>
#include <engine/HeadlessContext.h>
#include <engine/Image.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <epoxy/gl.h>

#include <chrono>
#include <iostream>
#include <memory>
#include <string>

int main(int argc, char** argv) {
    const bool plugin = argc == 4 && std::string(argv[3]) == "--plugin";
    if (argc != 3 && !plugin) {
        std::cerr << "usage: host-app SCENE.gltf OUT.png [--plugin]\n";
        return 2;
    }
    try {
        // A current OpenGL 4.5 core context first: the engine needs one for its whole life. Surfaceless EGL
        // needs no display server (Mesa's llvmpipe is enough).
        engine::HeadlessContext context;
        const content::LoadedScene loaded = content::GltfLoader::load(argv[1]);
        const auto camera = loaded.scene.firstCamera();
        if (!camera) {
            std::cerr << "host-app: " << argv[1] << " has no camera\n";
            return 1;
        }

        engine::Engine engine;
        if (plugin) {
            // By name: the loader finds libgs_module_shadows.so in the installed library folder.
            engine.moduleLoader().addSearchPath(GS_MODULE_DIR);
            engine.loadModule("shadows");
        } else {
            shadows::ShadowSettings settings;
            settings.technique = shadows::ShadowTechnique::PcfGsmQuadratic;
            engine.addModule(std::make_unique<shadows::ShadowModule>(settings));
        }

        engine::RenderTarget target({640, 480});
        // The first frame compiles shader variants and allocates shadow maps; time the second.
        engine.renderFrame(loaded.scene, *camera, target);
        glFinish();
        // glFinish + a steady clock: GL timer queries only time command submission on software renderers.
        const auto start = std::chrono::steady_clock::now();
        const engine::FrameStats stats = engine.renderFrame(loaded.scene, *camera, target);
        glFinish();
        const std::chrono::duration<double, std::milli> frameTime = std::chrono::steady_clock::now() - start;

        engine::writePng(argv[2], target.readPixels());
        std::cout << "host-app: " << argv[2] << ", shadow module " << (plugin ? "loaded as plugin" : "linked")
                  << ", " << stats.triangles << " triangles, frame " << frameTime.count()
                  << " ms (glFinish + steady clock) on " << context.renderer() << "\n";
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "host-app: " << error.what() << "\n";
        return 1;
    }
}
