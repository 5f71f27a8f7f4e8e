// Draws the streamed JPEG frames onto a canvas. The canvas takes the size of the last
// full-resolution frame, and every frame is scaled to fill it: right after a move the server
// sends reduced-resolution frames (`moving`), which should not make the view jump in size or
// lose its last sharp image's size. CSS (object-fit: contain) keeps the aspect when the canvas
// is shown larger or smaller than its resolution.

export class Viewer {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d', { alpha: false });
    this.lastDrawn = -1;  // frame number of the image on the canvas
    this.decoding = null; // { frame, blob } being decoded
    this.next = null;     // newest frame waiting for the decoder
    this.framesDrawn = 0;
  }

  // The image's resolution: the canvas's own size, so its aspect is the image's.
  setResolution(width, height) {
    if (!(width > 0 && height > 0)) return;
    if (this.canvas.width === width && this.canvas.height === height) return;
    this.canvas.width = width; // also clears the canvas
    this.canvas.height = height;
  }

  // A new session or scene: frame numbers may start again.
  reset() {
    this.lastDrawn = -1;
    this.next = null;
  }

  // Decoding is asynchronous and can take longer than the server takes to send the next frame;
  // only the newest waiting frame is kept, so a slow client shows the latest image, not a backlog.
  show(meta, blob) {
    this.next = { meta, blob };
    if (!this.decoding) this.decodeNext();
  }

  async decodeNext() {
    while (this.next) {
      const { meta, blob } = this.next;
      this.next = null;
      this.decoding = meta;
      try {
        const bitmap = await createImageBitmap(blob);
        // Frame numbers only grow within a session; an older frame finishing late is dropped.
        if (meta.frame > this.lastDrawn) {
          // Full-resolution frames set the canvas size (and so its aspect); reduced ones while
          // moving are scaled up to it.
          if (!meta.moving) this.setResolution(bitmap.width, bitmap.height);
          this.ctx.drawImage(bitmap, 0, 0, this.canvas.width, this.canvas.height);
          this.lastDrawn = meta.frame;
          this.framesDrawn += 1;
          this.canvas.dataset.frame = String(meta.frame); // lets tests wait for a drawn frame
          this.canvas.dataset.framesDrawn = String(this.framesDrawn);
        }
        bitmap.close();
      } catch (err) {
        console.warn('geodesic: a frame could not be decoded', err);
      }
    }
    this.decoding = null;
  }
}
