// The API, called exactly as any client calls it: JSON in, JSON or problem+json out.
// Write routes take the bearer token typed into the page (DENAVIT_API_TOKEN). The token is
// kept only in this module's private variable, for this page: never in sessionStorage,
// localStorage, a cookie or a URL, where any script of the origin could read it without the
// user. The field is cleared once read; a reload asks for the token again (docs/viewer.md).

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

let token = '';

// The token field: typing a token (then Enter or leaving the field) sets it and empties the
// field; "Clear" forgets it. The page shows only whether a token is set.
export function setupToken() {
  const input = document.getElementById('token');
  const state = document.getElementById('token-state');
  const clear = document.getElementById('token-clear');
  sessionStorage.removeItem('denavit-token'); // where an earlier viewer kept it
  const show = () => {
    state.textContent = token ? 'token set' : 'no token';
    clear.disabled = !token;
  };
  input.addEventListener('change', () => {
    const typed = input.value.trim();
    input.value = '';
    if (typed) token = typed;
    show();
  });
  clear.addEventListener('click', () => {
    token = '';
    show();
  });
  show();
}

// `blob`: the answer's body as a Blob (an image), else parsed JSON (or text).
async function call(method, path, body, blob = false) {
  const headers = { Accept: blob ? '*/*' : 'application/json' };
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
