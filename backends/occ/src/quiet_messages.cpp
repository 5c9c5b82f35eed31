#include "quiet_messages.hpp"

#include <Message.hxx>
#include <Message_Messenger.hxx>

namespace semimesh::occ {

QuietMessages::QuietMessages() {
  const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
  removed_ = messenger->Printers();
  messenger->ChangePrinters().Clear();
}

QuietMessages::~QuietMessages() {
  const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
  for (Message_SequenceOfPrinters::Iterator printer(removed_); printer.More(); printer.Next())
    messenger->AddPrinter(printer.Value());
}

}  // namespace semimesh::occ
