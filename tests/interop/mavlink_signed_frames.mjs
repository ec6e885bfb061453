// Signed MAVLink 2 frames from node-mavlink, an implementation independent of kestrel's, and
// node-mavlink's verdict on kestrel's (tests/interop/check_mavlink_signing.sh).
//   node mavlink_signed_frames.mjs write OUT.json   frames node-mavlink builds and signs
//   node mavlink_signed_frames.mjs check IN.json    each of kestrel's frames: does the signature
//                                                   match the key, and does node-mavlink, decoding
//                                                   it and signing it again with the same link id
//                                                   and timestamp, give the same bytes?
import { readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const { MavLinkProtocolV2, MavLinkPacketSignature } = require('node-mavlink');
const { minimal, common } = require('mavlink-mappings');

// The key both sides use: SHA-256 of a passphrase, as Mission Planner and node-mavlink make keys.
const key = MavLinkPacketSignature.key('kestrel interop signing');
const classes = {
  HEARTBEAT: minimal.Heartbeat,
  COMMAND_LONG: common.CommandLong,
  SET_POSITION_TARGET_LOCAL_NED: common.SetPositionTargetLocalNed,
  ATTITUDE_QUATERNION: common.AttitudeQuaternion,
  SETUP_SIGNING: common.SetupSigning,
};
const epochMs = Date.UTC(2015, 0, 1);

function message(name, fields) {
  const m = new classes[name]();
  Object.assign(m, fields);
  return m;
}

function signed(msg, { sysid, compid, seq, linkId, timestampMs }) {
  const protocol = new MavLinkProtocolV2(sysid, compid, MavLinkProtocolV2.IFLAG_SIGNED);
  return protocol.sign(protocol.serialize(msg, seq), linkId, key, timestampMs);
}

function write(out) {
  const t0 = Date.UTC(2026, 11, 4, 10, 0, 0);
  const cases = [
    ['HEARTBEAT', { type: 2, autopilot: 12, baseMode: 157, customMode: 6 << 16, systemStatus: 4, mavlinkVersion: 3 },
      { sysid: 1, compid: 1, seq: 0, linkId: 0 }],
    ['COMMAND_LONG', { targetSystem: 1, targetComponent: 1, command: 183, confirmation: 0, _param1: 9, _param2: 1900 },
      { sysid: 1, compid: 191, seq: 17, linkId: 2 }],
    ['SET_POSITION_TARGET_LOCAL_NED', { timeBootMs: 123456, targetSystem: 1, targetComponent: 1, coordinateFrame: 1,
      typeMask: 0x0DC0, x: 1.5, y: -2.25, z: -3, vx: 0.5, vy: 0, vz: -0.125, yaw: 1.5 },
      { sysid: 1, compid: 191, seq: 255, linkId: 2 }],
    ['ATTITUDE_QUATERNION', { timeBootMs: 42, q1: 0.5, q2: 0.5, q3: -0.5, q4: 0.5, rollspeed: 0.25, pitchspeed: -1,
      yawspeed: 2, reprOffsetQ: [1, 0, 0, 0] }, { sysid: 1, compid: 1, seq: 3, linkId: 0 }],
    ['SETUP_SIGNING', { targetSystem: 1, targetComponent: 1, secretKey: [...key],
      initialTimestamp: BigInt(t0 - epochMs) * 100n }, { sysid: 255, compid: 190, seq: 9, linkId: 1 }],
  ];
  const frames = cases.map(([name, fields, ids], i) => {
    const timestampMs = t0 + 10 * i;
    return { name, ...ids, timestamp: (timestampMs - epochMs) * 100, hex: signed(message(name, fields), { ...ids, timestampMs }).toString('hex') };
  });
  writeFileSync(out, JSON.stringify({ key: key.toString('hex'), frames }, null, 1));
}

function check(input) {
  const { frames } = JSON.parse(readFileSync(input, 'utf8'));
  const protocol = new MavLinkProtocolV2();
  const verdicts = frames.map(f => {
    const buffer = Buffer.from(f.hex, 'hex');
    const header = protocol.header(buffer);
    const signature = protocol.signature(buffer, header);
    const clazz = Object.values(classes).find(c => c.MSG_ID === header.msgid);
    const decoded = protocol.data(protocol.payload(buffer), clazz);
    const again = signed(decoded, {
      sysid: header.sysid, compid: header.compid, seq: header.seq, linkId: signature.linkId,
      timestampMs: signature.timestamp / 100 + epochMs,
    });
    return {
      name: clazz.MSG_NAME,
      signed: signature !== null,
      matches: signature !== null && signature.matches(key),
      same_bytes: again.toString('hex') === f.hex,
      link_id: signature.linkId,
      timestamp: signature.timestamp,
    };
  });
  process.stdout.write(JSON.stringify(verdicts, null, 1) + '\n');
}

const [mode, file] = process.argv.slice(2);
if (mode === 'write') write(file);
else if (mode === 'check') check(file);
else {
  process.stderr.write('usage: mavlink_signed_frames.mjs write OUT.json | check IN.json\n');
  process.exit(2);
}
