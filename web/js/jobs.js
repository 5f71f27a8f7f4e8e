// Render jobs from the page (docs/protocol.md, "Render jobs"): submits the current view at full
// quality (POST /api/jobs), lists every job with its progress, links the results of finished
// ones and cancels queued or running ones. The daemon keeps the jobs: reloading the page, or
// restarting the daemon, loses none. With a daemon token (the page's ?token=), every request
// carries it; download links carry it as a query parameter, since a link cannot set headers.

const POLL_MS = 1000;
const FORMATS = ['png', 'exr', 'jpg'];

export class JobsPanel {
  // ui: { button, status, list, spp }; token: the daemon's bearer token or null.
  constructor(ui, token) {
    this.ui = ui;
    this.token = token;
    this.available = true; // false once the server says it has no jobs API
    this.timer = null;
  }

  headers(extra = {}) {
    return this.token ? { ...extra, Authorization: `Bearer ${this.token}` } : extra;
  }

  link(url) {
    return this.token ? `${url}?token=${encodeURIComponent(this.token)}` : url;
  }

  say(text, bad = false) {
    this.ui.status.textContent = text;
    this.ui.status.classList.toggle('bad', bad);
  }

  // job: the request body without the stop condition, which comes from the panel.
  async submit(job) {
    const spp = Number.parseInt(this.ui.spp.value, 10);
    this.say('submitting…');
    try {
      const response = await fetch('/api/jobs', {
        method: 'POST',
        headers: this.headers({ 'Content-Type': 'application/json' }),
        body: JSON.stringify({ ...job, spp }),
      });
      if ([404, 405, 501].includes(response.status)) {
        this.available = false;
        this.say('render jobs not available on this server', true);
        return;
      }
      const body = await response.json().catch(() => ({}));
      if (!response.ok) {
        this.say(`render job refused: ${body.error || response.statusText || response.status}`, true);
        return;
      }
      this.say(`render job ${body.id} queued`);
      this.refresh();
    } catch {
      this.say('render job not sent: server unreachable', true);
    }
  }

  async cancel(id) {
    try {
      const response = await fetch(`/api/jobs/${id}`, { method: 'DELETE', headers: this.headers() });
      const body = await response.json().catch(() => ({}));
      if (!response.ok) this.say(`job ${id} not cancelled: ${body.error || response.status}`, true);
      else this.say(`render job ${id} cancelled`);
    } catch {
      this.say('cancel not sent: server unreachable', true);
    }
    this.refresh();
  }

  // Polls the job list for as long as the page is open (the list is short and cheap).
  start() {
    this.refresh();
    this.timer = setInterval(() => this.refresh(), POLL_MS);
  }

  async refresh() {
    if (!this.available) return;
    try {
      const response = await fetch('/api/jobs', { headers: this.headers() });
      if (!response.ok) return;
      const { jobs } = await response.json();
      this.show(jobs.slice().reverse()); // newest first
    } catch {
      // unreachable: the connection banner says so; the next poll tries again
    }
  }

  show(jobs) {
    const items = jobs.map((job) => this.item(job));
    this.ui.list.replaceChildren(...items);
    this.ui.list.hidden = items.length === 0;
  }

  item(job) {
    const li = document.createElement('li');
    li.className = `job ${job.state}`;
    li.dataset.id = String(job.id);
    li.dataset.state = job.state;
    const title = document.createElement('span');
    title.className = 'job-title';
    title.textContent = `#${job.id} ${job.scene} ${job.width}×${job.height}`;
    const state = document.createElement('span');
    state.className = 'job-state';
    const percent = Math.floor(job.progress * 100);
    state.textContent = ['queued', 'running'].includes(job.state)
      ? `${job.state} ${percent}% · ${job.samples} spp`
      : `${job.state} · ${job.samples} spp · ${job.elapsed.toFixed(1)} s`;
    const bar = document.createElement('progress');
    bar.max = 1;
    bar.value = job.progress;
    li.append(title, state, bar);

    const actions = document.createElement('span');
    actions.className = 'job-actions';
    if (job.state === 'queued' || job.state === 'running') {
      const cancel = document.createElement('button');
      cancel.type = 'button';
      cancel.className = 'job-cancel';
      cancel.textContent = 'Cancel';
      cancel.addEventListener('click', () => this.cancel(job.id));
      actions.append(cancel);
    }
    for (const format of FORMATS.filter((f) => job.results[f])) {
      const a = document.createElement('a');
      a.href = this.link(job.results[format]);
      a.download = `job-${job.id}.${format}`;
      a.textContent = format;
      actions.append(a);
    }
    if (job.samples > 0) {
      const report = document.createElement('a');
      report.href = this.link(job.report.csv);
      report.download = `job-${job.id}-report.csv`;
      report.textContent = 'report';
      actions.append(report);
    }
    if (job.message) {
      const why = document.createElement('span');
      why.className = 'job-message';
      why.textContent = job.message;
      actions.append(why);
    }
    li.append(actions);
    return li;
  }
}
