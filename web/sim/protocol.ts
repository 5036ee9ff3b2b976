// Messages between the page and the simulation worker.
import type { Frame, Layout } from '../types';

export type ToWorker =
  | { type: 'load'; scenario: string }
  | { type: 'play' }
  | { type: 'pause' }
  | { type: 'step'; count: number }
  | { type: 'seek'; step: number }
  | { type: 'check' }
  | { type: 'speed'; stepsPerSecond: number }
  | { type: 'overlay'; field: string | null }
  | { type: 'chart'; metric: string | null; points: number }
  | { type: 'apply'; action: string }
  | { type: 'inspect'; cell: number; id: number }
  | { type: 'ack' }
  | { type: 'crash' }
  | { type: 'ping'; id: number };

export type FromWorker =
  | { type: 'ready' }
  | { type: 'loaded'; layout: Layout; scenario: string }
  | { type: 'frame'; frame: Frame }
  | { type: 'playing'; playing: boolean }
  | { type: 'scenario'; scenario: string }
  | { type: 'inspected'; id: number; cell: number; facts: Record<string, unknown> }
  | { type: 'error'; message: string; context: 'load' | 'apply' | 'step' }
  | { type: 'panic'; message: string }
  | { type: 'pong'; id: number }
  | { type: 'goal'; met: boolean; because: string; steps: number };
