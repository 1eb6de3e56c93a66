"""The protocol's E2E CRC written independently of tread's C++ (for the Python cross-checks):
CRC-8/SAE-J1850 (poly 0x1D, init 0xFF, xorout 0xFF) over the data ID (the 11-bit CAN ID, low byte
first) and the payload after the CRC byte."""


def crc8_sae_j1850(data, crc=0xFF):
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1D) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc ^ 0xFF


def e2e_crc(frame_id, payload):
    return crc8_sae_j1850(bytes([frame_id & 0xFF, frame_id >> 8]) + bytes(payload[1:]))
