#include <dlfcn.h>

#include <filesystem>
#include <memory>
#include <string>

#include "peer.hpp"

namespace fast {

std::unique_ptr<Peer> load_llvmpipe_peer(int width, int height, int threads) {
#ifdef RASTERLAB_PEER_MODULE
    const std::filesystem::path module = RASTERLAB_PEER_MODULE;
    // Loaded once and never unloaded: Mesa keeps threads and state that
    // would outlive an unloaded module.
    void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        throw PeerUnavailable("the llvmpipe peer's module could not be loaded (" +
                              std::string(dlerror()) + ")");
    using Make = Peer* (*)(int, int, int, std::string*);
    const auto make = reinterpret_cast<Make>(dlsym(handle, "rasterlab_make_llvmpipe_peer"));
    if (!make) throw PeerUnavailable(module.string() + " has no rasterlab_make_llvmpipe_peer");
    std::string error;
    std::unique_ptr<Peer> peer(make(width, height, threads, &error));
    if (!peer) throw PeerUnavailable(error);
    return peer;
#else
    (void)width, (void)height, (void)threads;
    throw PeerUnavailable(
        "this build has none (OSMesa, libosmesa6-dev, missing; or a sanitized build)");
#endif
}

}  // namespace fast
