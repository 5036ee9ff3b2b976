// A "copy link" button's answer: the link on the clipboard, kept on the button (`data-link`), and
// for two seconds what became of it (the clipboard may be refused, and the link is then only in
// the address bar) before the button reads `label` again.

/** Puts `url` on the clipboard for `button` and says so on it. */
export async function copyLink(button: HTMLElement, url: string, label: string): Promise<void> {
  button.dataset.link = url;
  try {
    await navigator.clipboard.writeText(url);
    button.textContent = 'Link copied';
  } catch {
    button.textContent = 'Link in address bar';
  }
  setTimeout(() => (button.textContent = label), 2000);
}
