// The server's API for this page's participant link. Requests go out one after another (a play event
// is stored before the answer that needs it); a refusal throws an Error with the server's reason.
const token = location.pathname.split('/')[2] || '';
const base = `/api/${token}`;
let queue = Promise.resolve();

async function request(method, path, body) {
  const response = await fetch(`${base}/${path}`, {
    method,
    headers: body === undefined ? {} : { 'Content-Type': 'application/json' },
    body: body === undefined ? undefined : JSON.stringify(body),
    cache: 'no-store',
  });
  const isJson = (response.headers.get('Content-Type') || '').startsWith('application/json');
  const value = isJson ? await response.json() : await response.arrayBuffer();
  if (!response.ok) {
    const error = new Error(isJson && value.error ? value.error : `the server answered ${response.status}`);
    error.status = response.status;
    throw error;
  }
  return value;
}

function queued(fn) {
  const next = queue.then(fn, fn);
  queue = next.catch(() => {});
  return next;
}

export const getTrial = () => queued(() => request('GET', 'trial'));
export const sendAnswer = (body) => queued(() => request('POST', 'answer', body));
export const sendEvent = (body) => queued(() => request('POST', 'event', body));
export const render = (body) => queued(() => request('POST', 'render', body));
export const soundBytes = (id) => request('GET', `sound/${id}`);
