#include "app/ViewOptions.h"

#include "app/TextParsing.h"
#include "core/ImageIO.h"

namespace gi::app {
namespace {

// A whole non-negative number, nothing around it.
bool parseCount(const std::string& text, int& value) {
    return parseInt(text, value) && value >= 0;
}

// "FRAME:REST" with a non-empty REST (which may hold further colons).
bool parseFrameItem(const std::string& item, int& frame, std::string& rest) {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos || colon + 1 >= item.size()) return false;
    if (!parseCount(item.substr(0, colon), frame)) return false;
    rest = item.substr(colon + 1);
    return true;
}

} // namespace

bool parseKeyEvents(const std::string& text, std::vector<KeyEvent>& keys, std::string& error) {
    std::size_t start = 0;
    do {
        const std::size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma - start);
        KeyEvent event;
        if (!parseFrameItem(item, event.frame, event.key)) {
            error = "--keys '" + text + "': expected FRAME:KEY,... (e.g. 2:G,4:F12)";
            return false;
        }
        keys.push_back(event);
        start = comma == std::string::npos ? comma : comma + 1;
    } while (start != std::string::npos);
    return true;
}

bool parseDropEvent(const std::string& text, DropEvent& drop, std::string& error) {
    if (!parseFrameItem(text, drop.frame, drop.path)) {
        error = "--drop '" + text + "': expected FRAME:FILE (e.g. 3:scene.gltf)";
        return false;
    }
    return true;
}

bool applyFrames(Config& config, const std::string&, const std::string& v, std::string& error) {
    if (!parseCount(v, config.frames) || config.frames < 1) {
        error = "--frames '" + v + "': expected a positive integer";
        return false;
    }
    return true;
}

bool applyScreenshot(Config& config, const std::string&, const std::string& v,
        std::string& error) {
    if (!core::hasExtension(v, ".png")) {
        error = "--screenshot " + v + ": the screenshot must be a .png file";
        return false;
    }
    config.screenshotPath = v;
    return true;
}

bool applyKeys(Config& config, const std::string&, const std::string& v, std::string& error) {
    return parseKeyEvents(v, config.keys, error);
}

bool applyDrop(Config& config, const std::string&, const std::string& v, std::string& error) {
    DropEvent drop;
    if (!parseDropEvent(v, drop, error)) return false;
    config.drops.push_back(drop);
    return true;
}

bool applyMoveFrames(Config& config, const std::string&, const std::string& v,
        std::string& error) {
    if (!parseCount(v, config.moveFrames) || config.moveFrames < 1) {
        error = "--move-frames '" + v + "': expected a positive integer";
        return false;
    }
    return true;
}

} // namespace gi::app
