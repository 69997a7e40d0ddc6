// The API, called exactly as any client calls it: JSON in, JSON or problem+json out.
// Write routes take the bearer token typed into the page (DENAVIT_API_TOKEN); it is kept
// for the tab only (sessionStorage), never in the URL.

export class ApiError extends Error {
  constructor(status, problem) {
    const where = problem && problem.field ? ` (${problem.field})` : '';
    super(`${status}${where}: ${problem ? problem.detail || problem.title : 'request failed'}`);
    this.status = status;
    this.problem = problem;
  }
}

// The path of robot `id`'s route `suffix` ('' for GET /robots/{id} itself).
export const robotPath = (id, suffix = '') => `/robots/${encodeURIComponent(id)}${suffix}`;

const tokenInput = () => document.getElementById('token');

export function setupToken() {
  const input = tokenInput();
  input.value = sessionStorage.getItem('denavit-token') || '';
  input.addEventListener('change', () => sessionStorage.setItem('denavit-token', input.value));
}

// `blob`: the answer's body as a Blob (an image), else parsed JSON (or text).
async function call(method, path, body, blob = false) {
  const headers = { Accept: blob ? '*/*' : 'application/json' };
  const token = tokenInput()?.value.trim();
  if (token) headers.Authorization = `Bearer ${token}`;
  if (body !== undefined) headers['Content-Type'] = 'application/json';
  const resp = await fetch(path, {
    method,
    headers,
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  const type = resp.headers.get('content-type') || '';
  if (!resp.ok) {
    const problem = type.includes('json') ? await resp.json().catch(() => null) : null;
    throw new ApiError(resp.status, problem);
  }
  if (blob) return resp.blob();
  return type.includes('json') ? resp.json() : resp.text();
}

export const api = {
  get: (path) => call('GET', path),
  post: (path, body) => call('POST', path, body),
  blob: (path) => call('GET', path, undefined, true),
};
