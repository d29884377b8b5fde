// Foxglove's WebSocket protocol (foxglove.websocket.v1), the client side: the page speaks to the
// server exactly as Foxglove or Lichtblick would. It subscribes to every channel advertised and
// hands each message (JSON) to onMessage(topic, message, channel).
"use strict";

class FoxgloveClient {
  constructor(url, handlers) {
    this.handlers = handlers;
    this.channels = new Map();      // channel id -> channel
    this.subscriptions = new Map(); // subscription id -> channel
    this.nextSubscription = 1;
    this.clientChannels = new Map(); // topic -> client channel id
    this.nextClientChannel = 1;
    this.decoder = new TextDecoder();
    this.encoder = new TextEncoder();
    this.serverInfo = null;
    this.ws = new WebSocket(url, ["foxglove.websocket.v1"]);
    this.ws.binaryType = "arraybuffer";
    this.ws.onopen = () => handlers.onOpen && handlers.onOpen();
    this.ws.onclose = (e) => handlers.onClose && handlers.onClose(e);
    this.ws.onerror = () => {};
    this.ws.onmessage = (e) => this.receive(e.data);
  }

  receive(data) {
    if (typeof data === "string") {
      const m = JSON.parse(data);
      if (m.op === "serverInfo") {
        this.serverInfo = m;
        this.handlers.onServerInfo && this.handlers.onServerInfo(m);
      } else if (m.op === "advertise") {
        const subs = [];
        for (const c of m.channels) {
          this.channels.set(c.id, c);
          const id = this.nextSubscription++;
          this.subscriptions.set(id, c);
          subs.push({ id, channelId: c.id });
        }
        if (subs.length) {
          this.ws.send(JSON.stringify({ op: "subscribe", subscriptions: subs }));
        }
      } else if (m.op === "unadvertise") {
        const gone = [];
        for (const id of m.channelIds) {
          this.channels.delete(id);
          for (const [sub, c] of this.subscriptions) {
            if (c.id === id) { this.subscriptions.delete(sub); gone.push(sub); }
          }
        }
        this.handlers.onUnadvertise && this.handlers.onUnadvertise(m.channelIds);
      } else if (m.op === "status") {
        this.handlers.onStatus && this.handlers.onStatus(m);
      }
      return;
    }
    const view = new DataView(data);
    if (view.byteLength < 13 || view.getUint8(0) !== 1) {
      return;
    }
    const channel = this.subscriptions.get(view.getUint32(1, true));
    if (!channel) {
      return;
    }
    const message = JSON.parse(this.decoder.decode(new Uint8Array(data, 13)));
    this.handlers.onMessage(channel.topic, message, channel);
  }

  /** Publishes a JSON message on a topic (the server must allow client publishing). */
  publish(topic, schemaName, message) {
    if (this.ws.readyState !== WebSocket.OPEN) {
      return;
    }
    let id = this.clientChannels.get(topic);
    if (id === undefined) {
      id = this.nextClientChannel++;
      this.clientChannels.set(topic, id);
      this.ws.send(JSON.stringify({
        op: "advertise",
        channels: [{ id, topic, encoding: "json", schemaName }],
      }));
    }
    const body = this.encoder.encode(JSON.stringify(message));
    const frame = new Uint8Array(5 + body.length);
    const view = new DataView(frame.buffer);
    view.setUint8(0, 1);
    view.setUint32(1, id, true);
    frame.set(body, 5);
    this.ws.send(frame);
  }
}

/** Decodes a foxglove.PointCloud of float32 x, y (metres) into a Float32Array of mm pairs. */
function decodePoints(cloud) {
  const raw = atob(cloud.data || "");
  const bytes = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) {
    bytes[i] = raw.charCodeAt(i);
  }
  const view = new DataView(bytes.buffer);
  const stride = cloud.point_stride || 8;
  const n = Math.floor(bytes.length / stride);
  const out = new Float32Array(2 * n);
  for (let i = 0; i < n; i++) {
    out[2 * i] = view.getFloat32(i * stride, true) * 1000;
    out[2 * i + 1] = view.getFloat32(i * stride + 4, true) * 1000;
  }
  return out;
}

/** Heading in degrees of a quaternion about z. */
function headingOf(q) {
  return (2 * Math.atan2(q.z, q.w) * 180) / Math.PI;
}

/** A foxglove.Pose in mm and degrees. */
function poseOf(p) {
  return { x: p.position.x * 1000, y: p.position.y * 1000, th: headingOf(p.orientation) };
}
