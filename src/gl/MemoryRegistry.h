// The record of every texture and buffer storage the creation helpers in gl/Objects.h
// allocate: its label, its report row and its size in bytes. The helpers record an object when
// they allocate its storage and the handle forgets it when it deletes the object, so a memory
// report read from here lists what is allocated now, not what a formula says should be.
//
// The record is one table per process, not an object passed to every creation helper: a
// handle's destructor knows only its GL name, and the helpers are called from some forty places
// in scene/, gi/ and render/ that would otherwise all carry a registry they never read. The
// process has one GL context at a time (the viewer's window, the command's or a test's headless
// context), so a GL name identifies one object. Who an allocation belongs to is said once, where
// the work starts: a MemoryScope attributes everything allocated while it is alive to its
// MemoryOwner, so two renderers in one process each report their own bytes.
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gi::gl {

// One line of a memory report: what a resource is and how many bytes it allocated.
struct MemoryItem {
    std::string name;
    std::size_t bytes = 0;
};

enum class StorageKind { Texture, Buffer };

// One live allocation. `row` is the report line it adds to: its label, or the name of the
// MemoryGroup it was allocated in.
struct Allocation {
    StorageKind kind = StorageKind::Texture;
    GLuint id = 0;
    std::string label;
    std::string row;
    std::size_t bytes = 0;
    std::uint64_t owner = 0;   // 0: allocated outside any MemoryScope
};

// Called by gl/Objects.cpp after allocating storage for `id`, and by the handles before
// deleting it. Recording a name again replaces its entry.
void recordAllocation(StorageKind kind, GLuint id, const char* label, std::size_t bytes);
void forgetAllocation(StorageKind kind, GLuint id) noexcept;

// Every live allocation in the process, in the order they were made.
[[nodiscard]] std::vector<Allocation> liveAllocations();

// Someone who allocates GPU memory and reports it (a FrameRenderer). Its rows are prefixed with
// `prefix` ("occupancy/"), so a part it holds can keep its own owner and still be told
// apart in the holder's report.
class MemoryOwner {
public:
    explicit MemoryOwner(std::string prefix = {});
    MemoryOwner(const MemoryOwner&) = delete;
    MemoryOwner& operator=(const MemoryOwner&) = delete;

    [[nodiscard]] std::uint64_t id() const { return mId; }
    [[nodiscard]] std::vector<Allocation> allocations() const;
    // The allocations summed per row, sorted by name.
    [[nodiscard]] std::vector<MemoryItem> report() const;

private:
    std::uint64_t mId;
    std::string mPrefix;
};

// While alive, what the helpers allocate (on this thread, where the GL context is current)
// belongs to `owner`. Scopes nest; the innermost wins.
class MemoryScope {
public:
    explicit MemoryScope(const MemoryOwner& owner);
    ~MemoryScope();
    MemoryScope(const MemoryScope&) = delete;
    MemoryScope& operator=(const MemoryScope&) = delete;

private:
    std::uint64_t mPrevious;
};

// While alive, what the helpers allocate is reported as one row `name` instead of a row per
// label: a scene's many material textures are one line, "scene/textures".
class MemoryGroup {
public:
    explicit MemoryGroup(std::string name);
    ~MemoryGroup();
    MemoryGroup(const MemoryGroup&) = delete;
    MemoryGroup& operator=(const MemoryGroup&) = delete;

private:
    std::string mName;
    const std::string* mPrevious;
};

// Sum of the items' bytes.
[[nodiscard]] std::size_t totalBytes(const std::vector<MemoryItem>& items);

} // namespace gi::gl
