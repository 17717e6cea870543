#pragma once
// Every temporary file and folder a run creates (atomic outputs, staging folders, scratch
// datasets) is registered here while it exists, so that an interrupted run can remove them
// all: install_interrupt_cleanup() makes SIGINT and SIGTERM stop the program, remove every
// registered path, print one line and exit 130 (SIGINT) or 143 (SIGTERM). Outputs that were
// already in place are untouched: temporaries are renamed over them only when complete.
//
// No code runs in a signal handler: the signals are blocked in every thread and a watcher
// thread takes them with sigwait(), so the cleanup may lock, allocate and walk folders.
#include <spawn.h>

#include <filesystem>
#include <functional>
#include <string>

namespace tunnelmap {

namespace TempRegistry {
// Registers `path` and runs `make`, which creates it (and may write it whole). An interrupt
// waits until `make` returns: the cleanup never runs between the registration and the
// creation, which would let the path appear after the cleanup. Once an interrupt has come,
// a new creation (outside a running `make`) waits for the exit instead of starting.
void create(const std::filesystem::path& path, const std::function<void()>& make);
void remove(const std::filesystem::path& path);  // call once it is renamed into place or deleted
// Runs `publish`, which renames the finished temporary `path` into place and returns whether
// it did, and then forgets `path`, unless an interrupt has come: an interrupt's cleanup and a
// publish never overlap, so an interrupted run never replaces an earlier output. After an
// interrupt it waits for the exit (nested in a running creation, it throws instead, so that
// the creation ends).
void publish(const std::filesystem::path& path, const std::function<bool()>& publish);
}  // namespace TempRegistry

// Call first thing in main(), before any thread starts (threads inherit the blocked signals).
// `program` starts the one-line message.
void install_interrupt_cleanup(const std::string& program);

// The signal mask a child process should start with: none blocked (posix_spawn inherits ours).
void unblock_interrupts_for_child(posix_spawnattr_t* attr);

}  // namespace tunnelmap
