package org.jaria.protocol;

/** Why a received packet (or a run of bytes) was thrown away. */
public enum DropReason {
  /** The checksum did not match: the bytes were damaged on the way. */
  BAD_CHECKSUM,
  /** The COUNT byte was below 3 or above 204: not the start of a real packet. */
  BAD_LENGTH,
  /** The packet stopped arriving half-way (no byte for the receive timeout). */
  TIMEOUT,
  /** The packet was well formed but its contents made no sense for its type. */
  MALFORMED,
  /** The program fell behind and its queue of received packets was full. */
  OVERFLOW
}
