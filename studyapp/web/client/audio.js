// Web Audio playback of one trial's sounds: each decoded once, played from the start, switched at the
// same sample with a 5 ms crossfade (MUSHRA), optionally looping. Every play/switch/stop is reported
// with the audio clock's time and the position in the sound, for the server's event log.
import { soundBytes } from './api.js';

const kCrossfadeS = 0.005;
const kLookaheadS = 0.01;  // start and switch times are scheduled this far ahead, on the audio clock

export class Player {
  constructor(onEvent, onChange) {
    this.context = new AudioContext();
    this.buffers = [];
    this.loop = false;
    this.current = null;  // { index, source, gain, startedAt, offset }
    this.onEvent = onEvent;    // (kind, index, at_ms, position_s)
    this.onChange = onChange;  // () after playing state changes
  }

  // Fetches and decodes every sound of the trial (ids from the page) once.
  async load(sounds) {
    this.stop(false);
    this.buffers = await Promise.all(sounds.map(async (s) => this.context.decodeAudioData(await soundBytes(s.id))));
  }

  async replace(index, id) {
    if (this.current && this.current.index === index) this.stop(false);
    this.buffers[index] = await this.context.decodeAudioData(await soundBytes(id));
  }

  playingIndex() { return this.current ? this.current.index : -1; }

  position(at) {
    const c = this.current;
    const duration = this.buffers[c.index].duration;
    const p = c.offset + (at - c.startedAt);
    return this.loop ? p % duration : Math.min(p, duration);
  }

  start(index, offset, at) {
    const source = new AudioBufferSourceNode(this.context, { buffer: this.buffers[index], loop: this.loop });
    const gain = new GainNode(this.context, { gain: 0 });
    source.connect(gain).connect(this.context.destination);
    gain.gain.setValueAtTime(0, at);
    gain.gain.linearRampToValueAtTime(1, at + kCrossfadeS);
    source.start(at, offset);
    const entry = { index, source, gain, startedAt: at, offset };
    source.onended = () => {
      if (this.current === entry) { this.current = null; this.onChange(); }
    };
    this.current = entry;
  }

  fadeOut(entry, at) {
    entry.gain.gain.setValueAtTime(1, at);
    entry.gain.gain.linearRampToValueAtTime(0, at + kCrossfadeS);
    entry.source.onended = null;
    entry.source.stop(at + kCrossfadeS);
  }

  async play(index) {
    await this.context.resume();
    const at = this.context.currentTime + kLookaheadS;
    if (this.current) this.fadeOut(this.current, at);
    this.start(index, 0, at);
    this.onEvent('play', index, at * 1000, 0);
    this.onChange();
  }

  // The same moment of another sound: both changes scheduled at one audio-clock time.
  async switchTo(index) {
    if (!this.current) return this.play(index);
    const at = this.context.currentTime + kLookaheadS;
    const position = Math.min(this.position(at), this.buffers[index].duration);
    this.fadeOut(this.current, at);
    this.start(index, position, at);
    this.onEvent('switch', index, at * 1000, position);
    this.onChange();
  }

  stop(report = true) {
    if (!this.current) return;
    const at = this.context.currentTime;
    const entry = this.current;
    this.current = null;
    this.fadeOut(entry, at);
    if (report) this.onEvent('stop', entry.index, at * 1000, this.positionOf(entry, at));
    this.onChange();
  }

  positionOf(entry, at) {
    const saved = this.current;
    this.current = entry;
    const p = this.position(at);
    this.current = saved;
    return p;
  }

  setLoop(loop) {
    this.loop = loop;
    if (this.current) this.current.source.loop = loop;
  }
}
