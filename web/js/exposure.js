// The exposure control: a slider in stops (display value = radiance x 2^stops) and an "auto"
// box (the server brings the image's log-average luminance to middle grey). The server
// applies it to the frames it encodes and sends the last frame again at once, so dragging the
// slider never restarts the accumulation (docs/protocol.md, `settings.exposure`).

const SEND_INTERVAL_MS = 100; // while dragging: at most one `settings` message this often

export class ExposureControl {
  // elements: { slider, value, auto }; send(exposure) sends a number of stops or 'auto'.
  constructor(elements, send) {
    this.el = elements;
    this.send = send;
    this.timer = null;
    this.pending = null;
    elements.slider.addEventListener('input', () => {
      this.showStops(Number.parseFloat(elements.slider.value));
      this.queue(Number.parseFloat(elements.slider.value));
    });
    elements.auto.addEventListener('change', () => {
      elements.slider.disabled = elements.auto.checked;
      this.queue(elements.auto.checked ? 'auto' : Number.parseFloat(elements.slider.value));
    });
  }

  // What the controls ask for: a number of stops or 'auto'.
  get value() {
    return this.el.auto.checked ? 'auto' : Number.parseFloat(this.el.slider.value);
  }

  // Shows an exposure (a scene's, or the one asked for) without sending it.
  show(exposure) {
    const automatic = exposure === 'auto';
    this.el.auto.checked = automatic;
    this.el.slider.disabled = automatic;
    if (!automatic) {
      this.el.slider.value = String(exposure);
      this.showStops(exposure);
    }
  }

  // A frame's exposure: under 'auto' the slider follows the stops the server chose.
  showFrame(stops) {
    if (!this.el.auto.checked || !Number.isFinite(stops)) return;
    this.el.slider.value = String(stops);
    this.showStops(stops);
  }

  showStops(stops) {
    this.el.value.textContent = `${stops >= 0 ? '+' : '−'}${Math.abs(stops).toFixed(2)}`;
  }

  queue(exposure) {
    this.pending = exposure;
    if (this.timer !== null) return;
    this.flush();
    this.timer = setInterval(() => {
      if (this.pending === null) {
        clearInterval(this.timer);
        this.timer = null;
      } else {
        this.flush();
      }
    }, SEND_INTERVAL_MS);
  }

  flush() {
    const exposure = this.pending;
    this.pending = null;
    this.send(exposure);
  }
}
