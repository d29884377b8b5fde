package org.jaria.net.server;

import java.nio.ByteBuffer;

/**
 * One whole ArNetworking packet waiting to be sent to a client. Published values' packets are
 * shared by every client that receives them (each item reads its own view); an unsent update of a
 * request is replaced by a newer one (see {@link OutboundQueue}).
 */
final class Outgoing {

  /** The packet's bytes as they go on the wire, position 0. */
  ByteBuffer payload;

  /** Version of the published value (updates only). */
  long version;

  /** Whether the bytes belong to this client alone (counts against the queue limit). */
  final boolean owned;

  /** Command of the request an update belongs to (for coalescing); -1 otherwise. */
  final int coalesceKey;

  /** Whether writing has begun (a started item is never replaced). */
  boolean started;

  private Outgoing(ByteBuffer payload, long version, boolean owned, int coalesceKey) {
    this.payload = payload;
    this.version = version;
    this.owned = owned;
    this.coalesceKey = coalesceKey;
  }

  /** A packet for this client alone (replies, control packets). */
  static Outgoing frame(byte[] wire) {
    return new Outgoing(ByteBuffer.wrap(wire).asReadOnlyBuffer(), 0, true, -1);
  }

  /** An update of a request for data {@code command}, coalesced with any unsent one. */
  static Outgoing update(int command, long version, ByteBuffer sharedWire) {
    return new Outgoing(sharedWire.duplicate(), version, false, command);
  }

  /** Puts a newer update's packet and version in place of this unsent one's. */
  void replaceUpdate(ByteBuffer newPayload, long newVersion) {
    payload = newPayload.duplicate();
    version = newVersion;
  }

  /** Bytes this item puts on the wire. */
  long size() {
    return payload.capacity();
  }
}
