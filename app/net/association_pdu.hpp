#pragma once

// Internal to net: the A-ASSOCIATE-RQ's PDU head as the association pool reads it before DCMTK
// does (association_pool over a plain socket, association_tls through a TLS connection).
#include <cstddef>
#include <cstdint>

namespace steerseg::net {

// An association request larger than this is no scanner's (a few kilobytes at most).
constexpr std::uint32_t kMaxRequestBytes = 1U << 20;
constexpr unsigned char kAssociateRequest = 0x01; // the PDU type (PS3.8 9.3.2)

constexpr std::size_t kPduHead = 6; // type, reserved, 32-bit length

inline std::uint32_t pduLength(const unsigned char* head) {
    return (std::uint32_t{head[2]} << 24U) | (std::uint32_t{head[3]} << 16U) |
           (std::uint32_t{head[4]} << 8U) | std::uint32_t{head[5]};
}

} // namespace steerseg::net
