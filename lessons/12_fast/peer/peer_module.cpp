// The llvmpipe peer as a module that lesson 12's program loads at run time
// (peer_loader.cpp): its one entry point makes a peer, or says why it cannot.
#include <exception>
#include <string>

#include "llvmpipe_peer.hpp"

// Exported with C linkage so that dlsym() finds it by this name. An error
// comes back as text rather than an exception across the module's edge.
extern "C" __attribute__((visibility("default"))) fast::Peer* rasterlab_make_llvmpipe_peer(
    int width, int height, int threads, std::string* error) {
    try {
        return new fast::LlvmpipePeer(width, height, threads);
    } catch (const std::exception& e) {
        *error = e.what();
        return nullptr;
    }
}
