// The page's features, each in its own folder and mounted in this order on the one page context
// (web/page/context.ts). A feature with a tab gets it in this order; a new feature is its folder
// and one line here. No feature imports another: they share the session and the page's events.
import type { Feature } from '../page/context';
import { about } from './about';
import { announce } from './announce';
import { compare } from './compare';
import { embed } from './embed';
import { exercise } from './exercise';
import { experiments } from './experiments';
import { gallery } from './gallery';
import { grade } from './grade';
import { inspect } from './inspect';
import { offline } from './offline';
import { record } from './record';
import { reproduction } from './reproduction';
import { rules } from './rules';
import { run } from './run';
import { scenario } from './scenario';
import { share } from './share';
import { welcome } from './welcome';

export const FEATURES: readonly Feature[] = [
  run,
  inspect,
  scenario,
  rules,
  exercise,
  compare,
  share,
  experiments,
  about,
  reproduction,
  gallery,
  grade,
  record,
  welcome,
  announce,
  embed,
  offline,
];
