#include "gl/MemoryRegistry.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>

namespace gi::gl {
namespace {

struct Table {
    std::mutex mutex;
    std::vector<Allocation> entries;
};

Table& table() {
    static Table instance;
    return instance;
}

// The allocation context of this thread: the GL context is current on one thread, and so is
// the work that allocates.
thread_local std::uint64_t tCurrentOwner = 0;
thread_local const std::string* tCurrentGroup = nullptr;

std::vector<Allocation>::iterator find(std::vector<Allocation>& entries, StorageKind kind,
        GLuint id) {
    return std::find_if(entries.begin(), entries.end(),
            [&](const Allocation& a) { return a.kind == kind && a.id == id; });
}

} // namespace

void recordAllocation(StorageKind kind, GLuint id, const char* label, std::size_t bytes) {
    Allocation entry{kind, id, label ? label : "", "", bytes, tCurrentOwner};
    entry.row = tCurrentGroup ? *tCurrentGroup : entry.label;
    Table& t = table();
    const std::lock_guard lock(t.mutex);
    if (const auto it = find(t.entries, kind, id); it != t.entries.end()) t.entries.erase(it);
    t.entries.push_back(std::move(entry));
}

void forgetAllocation(StorageKind kind, GLuint id) noexcept {
    Table& t = table();
    const std::lock_guard lock(t.mutex);
    if (const auto it = find(t.entries, kind, id); it != t.entries.end()) t.entries.erase(it);
}

std::vector<Allocation> liveAllocations() {
    Table& t = table();
    const std::lock_guard lock(t.mutex);
    return t.entries;
}

MemoryOwner::MemoryOwner(std::string prefix) : mPrefix(std::move(prefix)) {
    static std::atomic<std::uint64_t> next{1};
    mId = next++;
}

std::vector<Allocation> MemoryOwner::allocations() const {
    std::vector<Allocation> mine = liveAllocations();
    std::erase_if(mine, [&](const Allocation& a) { return a.owner != mId; });
    return mine;
}

std::vector<MemoryItem> MemoryOwner::report() const {
    std::map<std::string, std::size_t> rows;
    for (const Allocation& a : allocations()) rows[mPrefix + a.row] += a.bytes;
    std::vector<MemoryItem> items;
    for (const auto& [name, bytes] : rows) items.push_back({name, bytes});
    return items;
}

MemoryScope::MemoryScope(const MemoryOwner& owner) : mPrevious(tCurrentOwner) {
    tCurrentOwner = owner.id();
}

MemoryScope::~MemoryScope() { tCurrentOwner = mPrevious; }

MemoryGroup::MemoryGroup(std::string name) : mName(std::move(name)), mPrevious(tCurrentGroup) {
    tCurrentGroup = &mName;
}

MemoryGroup::~MemoryGroup() { tCurrentGroup = mPrevious; }

std::size_t totalBytes(const std::vector<MemoryItem>& items) {
    std::size_t total = 0;
    for (const MemoryItem& item : items) total += item.bytes;
    return total;
}

} // namespace gi::gl
