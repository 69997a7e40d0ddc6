// One request in flight per kind, the latest wins: while a request runs, newer calls
// replace each other and the last one runs when it ends (sliders and drags call often).
// `Latest.pending` counts the schedulers with work not yet done (tests wait for 0).

export class Latest {
  static pending = 0;

  constructor(task, onError) {
    this.task = task;
    this.onError = onError;
    this.running = false;
    this.next = null;
  }

  // Ask for task(...args); resolves when this call's task, or a newer one, has run.
  request(...args) {
    if (!this.running && this.next === null) Latest.pending += 1;
    this.next = args;
    if (!this.running) this._drain();
  }

  async _drain() {
    this.running = true;
    while (this.next !== null) {
      const args = this.next;
      this.next = null;
      try {
        await this.task(...args);
      } catch (err) {
        this.onError(err);
      }
    }
    this.running = false;
    Latest.pending -= 1;
  }
}
