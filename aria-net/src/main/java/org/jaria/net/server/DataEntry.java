package org.jaria.net.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.nio.ByteBuffer;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.DataInfo;

/**
 * A registered data: its description, and either a request handler or a publication. For a
 * publication it caches the encoding of the latest version, so a value is encoded once however many
 * clients receive it (ArNetworking calls the handler for each client; the bytes are the same).
 */
final class DataEntry {

  final DataInfo info;
  final Where where;
  final RequestHandler handler;
  final Publication publication;

  /** How requests of this data wait for the robot's cycle. */
  volatile CallPolicy policy = CallPolicy.QUEUED;

  @GuardedBy("this")
  private long encodedVersion = Long.MIN_VALUE;

  @GuardedBy("this")
  private ByteBuffer encoded;

  DataEntry(DataInfo info, Where where, RequestHandler handler, Publication publication) {
    this.info = info;
    this.where = where;
    this.handler = handler;
    this.publication = publication;
  }

  /** A published value's whole packet (command, body, checksum), for one version. */
  record Encoded(long version, ByteBuffer wire) {}

  /**
   * The current published value, encoded (read-only, shared; null if nothing was published yet).
   * Encodes only when the version changed since the last call.
   */
  synchronized Encoded currentEncoded() {
    Versioned v = publication.current();
    if (v.value() == null) {
      return null;
    }
    if (encoded == null || v.version() != encodedVersion) {
      ArNetPacket p = new ArNetPacket(info.id());
      v.value().write(p);
      encoded = ByteBuffer.wrap(p.toWire()).asReadOnlyBuffer();
      encodedVersion = v.version();
    }
    return new Encoded(encodedVersion, encoded);
  }

  String name() {
    return info.name();
  }

  int id() {
    return info.id();
  }
}
