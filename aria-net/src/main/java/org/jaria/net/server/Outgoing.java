package org.jaria.net.server;

import java.nio.ByteBuffer;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.Protocol;

/**
 * One thing waiting to be sent to a client: either a complete frame, or a RESPONSE/UPDATE payload
 * that is written as one or more part frames (each at most {@link Protocol#PART_SIZE} bytes of
 * payload), with headers made as they are written. Payloads may be shared by many clients: each
 * item reads its own view.
 */
final class Outgoing {

  /** RESPONSE or UPDATE for a payload; null for a complete frame. */
  final Kind kind;

  /** Request id (RESPONSE) or data id (UPDATE). */
  final long first;

  /** Data id (RESPONSE) or version (UPDATE; replaced when a newer update is coalesced). */
  long second;

  /** The payload (or the whole frame), position 0. */
  ByteBuffer payload;

  /** Whether the payload belongs to this client alone (counts against the queue limit). */
  final boolean owned;

  /** Data id of the subscription an UPDATE belongs to (for coalescing); -1 otherwise. */
  final int coalesceKey;

  /** Whether writing has begun (a started item is never replaced). */
  boolean started;

  /** Payload bytes already handed to part frames. */
  int partOffset;

  private boolean partsDone;

  private Outgoing(
      Kind kind, long first, long second, ByteBuffer payload, boolean owned, int coalesceKey) {
    this.kind = kind;
    this.first = first;
    this.second = second;
    this.payload = payload;
    this.owned = owned;
    this.coalesceKey = coalesceKey;
  }

  /** A complete, owned frame (control messages, errors). */
  static Outgoing frame(byte[] frame) {
    return new Outgoing(null, 0, 0, ByteBuffer.wrap(frame).asReadOnlyBuffer(), true, -1);
  }

  /** A RESPONSE to request {@code reqId} of data {@code dataId}. */
  static Outgoing response(int reqId, int dataId, ByteBuffer payload, boolean owned) {
    return new Outgoing(Kind.RESPONSE, reqId, dataId, payload.duplicate(), owned, -1);
  }

  /** An UPDATE of subscription {@code dataId}, coalesced with any unsent one. */
  static Outgoing update(int dataId, long version, ByteBuffer sharedPayload) {
    return new Outgoing(Kind.UPDATE, dataId, version, sharedPayload.duplicate(), false, dataId);
  }

  /** Puts a newer update's payload and version in place of this unsent one's. */
  void replaceUpdate(ByteBuffer newPayload, long newVersion) {
    payload = newPayload;
    second = newVersion;
  }

  /** Bytes this item puts on the wire (approximately, for accounting). */
  long size() {
    if (kind == null) {
      return payload.capacity();
    }
    int parts = Math.max(1, (payload.capacity() + Protocol.PART_SIZE - 1) / Protocol.PART_SIZE);
    return payload.capacity() + (long) parts * Frames.MAX_HEADER_BYTES;
  }

  /**
   * Prepares the next frame to write into {@code bufs} (header, payload slice).
   *
   * @return false when every frame of the item has been prepared
   */
  boolean nextFrame(ByteBuffer header, ByteBuffer[] bufs) {
    if (partsDone) {
      return false;
    }
    if (kind == null) {
      header.clear().flip();
      bufs[0] = header;
      bufs[1] = payload;
      partsDone = true;
      return true;
    }
    int total = payload.capacity();
    int len = Math.min(Protocol.PART_SIZE, total - partOffset);
    boolean last = partOffset + len >= total;
    Frames.putHeader(header, kind, first, second, last, len);
    ByteBuffer slice = payload.duplicate();
    slice.limit(partOffset + len).position(partOffset);
    bufs[0] = header;
    bufs[1] = slice;
    partOffset += len;
    partsDone = last;
    return true;
  }
}
