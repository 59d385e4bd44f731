// The editor's pick: what the G-buffer holds under the cursor (host/device shared).
#ifndef PPR_PICK_H
#define PPR_PICK_H
#include "shader/shared.h"

PPR_BEGIN
struct PickPush {
    ivec2 pixel;
    uint pad0, pad1;
};
struct PickResult {
    vec4 position;     // world space; w = 1 when a surface is there, 0 for sky or off screen
    vec4 normal;       // world-space geometric normal of that surface (from the depths around it)
    uint reflectorId;  // G-buffer reflector id (index + 1), 0 = none
    uint pad0, pad1, pad2;
};
PPR_END
PPR_SIZE_CHECK(PickPush, 16);
PPR_SIZE_CHECK(PickResult, 48);

#endif
