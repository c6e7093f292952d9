// Starts `cantools-od lsp` for EDS, DCF and XDD/XDC documents; every feature comes from the server.
import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions } from "vscode-languageclient/node";

let client: LanguageClient | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  const settings = vscode.workspace.getConfiguration("cantools-od");
  const [command, ...args] = settings.get<string[]>("command", ["cantools-od", "lsp"]);
  const server: ServerOptions = { command, args };
  const options: LanguageClientOptions = {
    documentSelector: [
      { scheme: "file", language: "canopen-eds" },
      { scheme: "file", language: "canopen-xdd" },
    ],
    initializationOptions: {
      nodeId: settings.get<number | null>("nodeId", null),
      canFd: settings.get<boolean>("canFd", false),
      profile: settings.get<string | null>("profile", null),
    },
    // A changed setting reaches the server (workspace/didChangeConfiguration), which checks every file again.
    synchronize: { configurationSection: "cantools-od" },
  };
  client = new LanguageClient("cantools-od", "cantools-od", server, options);
  context.subscriptions.push(client);
  await client.start();
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
