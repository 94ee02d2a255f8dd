// Direction of a frame on a master/slave link: who sent it decides how it is laid out (a Modbus
// FC 3 request and response differ; an HCS error response is recognised only in a response).
#pragma once

#include <cstdint>

namespace vt::dev {

enum class Direction : std::uint8_t {
    Request,  // master (PLC, ValveTune) → node / module
    Response, // node / module → master
};

} // namespace vt::dev
